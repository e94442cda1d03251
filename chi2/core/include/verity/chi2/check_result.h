// What an adapter's check returns: the sampling test with its two statistical verdicts
// (chi-square on the shape, pdf integral on the normalisation) and the per-sample audit,
// plus a list of what failed, by name, to print or assert on.
#pragma once

#include <verity/chi2/delta_check.h>
#include <verity/chi2/sampling_check.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace verity::chi2 {

// Each check runs two statistical tests (chi-square and pdf integral): a caller that runs
// n checks at a family-wise level α uses sidakLevel(α, kStatisticalTestsPerCheck · n).
// A BSDF check adds one test per expected delta-lobe share or albedo it states
// (DeltaCheckOptions::statisticalTests()).
inline constexpr int kStatisticalTestsPerCheck = 2;

// What every adapter's check is told.
struct CheckOptions {
  std::string name;  // printed, and the seed's source (seedFromName) unless `seed` is set
  // The per-test level in (0, 1), required: e.g. sidakLevel(0.01, kStatisticalTestsPerCheck · n)
  // for n checks at a family-wise level of 1%.
  double significance = 0;
  long long samples = 1'000'000;
  std::optional<uint64_t> seed;
  // Cells in cos θ on the sphere (twice as many in φ) or along each side of a planar
  // domain; 0: 32 on the sphere and 40 on a plane, as in Verity's suite.
  int resolution = 0;
  // The probability at which the report states what the check could have caught.
  double power = kDefaultPower;
  // The caller's question (power.h): when set, `samples` is ignored and the check draws as
  // many as finding this target needs, at most maxSamples; beyond that it is INCONCLUSIVE.
  std::optional<DetectionTarget> detect;
  long long maxSamples = 100'000'000;
  // The per-sample comparisons on the first this many samples only (whole streams), which
  // the report states with what they could have met; on every sample when unset
  // (TestOptions::auditedSamples).
  std::optional<long long> auditedSamples;
  // Cells of equal probability under the claimed pdf (partition.h), so that a narrow lobe
  // keeps its degrees of freedom; or the uniform grid, cheaper to integrate (Verity's own
  // sweep uses it: TestOptions::cells).
  CellLayout cells = CellLayout::EqualProbability;
  // Where the check has got to, updated as it runs, for a display (phase_times.h); none if null.
  CheckProgress* progress = nullptr;
  // The threads the check runs on, in a task arena of its own; 0: every core. With 1 it runs
  // on the calling thread alone, the model's functions included: for a library that binds its
  // state to a thread (Dr.Jit's scopes). The result is the same for any count.
  int threads = 0;
};

struct CheckResult {
  TestResult test;
  long long deltaSamples = 0;  // delta-lobe samples, counted and not histogrammed
  DeltaCheck delta;            // their own checks (delta_check.h), where there were any

  // PASSED, FAILED, or INCONCLUSIVE when a check could not run with its stated power
  // (inconclusiveReason() says why); FAILED too when the delta lobes fail, and INCONCLUSIVE
  // when a sampling test that passed leaves a delta lobe's stated albedo untested. passed()
  // only on PASSED.
  Verdict verdict() const;
  // The sampling test's reason (TestResult::inconclusiveReason), else the delta lobes'.
  std::string inconclusiveReason() const;
  bool passed() const { return verdict() == Verdict::Passed; }
  // "chi-square", "pdf integral", "samples outside the domain", "inconclusive" and the
  // audit's defects ("weight != eval*cos/pdf", "reciprocity", ...: defectName()); empty
  // when it passed.
  std::vector<std::string> failures() const;
  bool failed(const std::string& check) const;
  std::string report() const;
};

// Runs one sampling test of `subject` as `options` say, seeded from `seedName` unless
// options.seed is set.
CheckResult runCheck(const Subject& subject, const CheckOptions& options,
                     const std::string& seedName);

}  // namespace verity::chi2
