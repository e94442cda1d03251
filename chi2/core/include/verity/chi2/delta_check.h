// The delta lobes of a BSDF (a smooth mirror, smooth glass, thin glass), which the chi-square
// test cannot histogram. Every sample with `delta` set is checked:
//   direction   the mirror of wi about +z; with DeltaCheckOptions::eta set, also the refraction
//               of wi for that relative index (Snell); without it, also −wi (straight through:
//               thin glass, an index-matched interface). Within `directionTolerance`.
//   weight      finite and non-negative.
// and each kind of lobe (reflection, refraction, pass-through) is measured over all N draws:
//   share       the fraction of draws that are samples of the lobe, with its Clopper–Pearson
//               interval (Clopper & Pearson 1934, Biometrika 26);
//   albedo      the lobe's contribution to E[weight], the mean over all draws of
//               weight·1[the lobe], with its Student t interval (the CLT; N − 1 degrees of
//               freedom), per component.
// Where the caller states an expected share or albedo, that value must lie in the interval at
// the check's level: one two-sided statistical test each. An albedo's components are tested
// together at the Šidák level for their number (Šidák 1967 holds for correlated normal means),
// so that each stated albedo counts as one test, and its interval is widened by
// kWeightTolerance relative, the per-sample weights' tolerance (a weight stored in float).
// The t interval rests on the central limit theorem for the lobe's weights, which a handful
// of draws in the lobe does not give (a lobe never drawn has an interval of width 0): a
// stated albedo above 0 of a lobe drawn fewer than kMinAlbedoDraws times is not tested, and
// the check is INCONCLUSIVE, saying so, rather than FAILED or PASSED.
#pragma once

#include <verity/chi2/audit.h>
#include <verity/chi2/bsdf_model.h>
#include <verity/chi2/sampling_check.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace verity::chi2 {

enum class DeltaLobe { Reflection, Refraction, PassThrough, Count };

const char* deltaLobeName(DeltaLobe lobe);  // "reflection", "refraction", "pass-through"

// What the caller knows of one lobe, e.g. the Fresnel reflectance at wi for both.
struct DeltaExpectation {
  std::optional<double> share;  // the probability that a draw samples this lobe
  // E[weight · 1[this lobe]]: one value per component, or one for all of them.
  std::optional<Eigen::ArrayXd> albedo;
};

struct DeltaCheckOptions {
  // The relative index of refraction η = η(below) / η(above), below being wo.z < 0 (1.5 for
  // glass in air). Unset: a delta transmission must go straight through (−wi).
  std::optional<double> eta;
  // Largest |wo − expected direction| accepted (about the angle in radians).
  double directionTolerance = 1e-4;
  std::array<DeltaExpectation, static_cast<int>(DeltaLobe::Count)> expected{};

  DeltaExpectation& expect(DeltaLobe lobe) { return expected[static_cast<int>(lobe)]; }
  // The statistical tests these options add to a check: one per stated share or albedo.
  int statisticalTests() const;
};

// The fewest draws of a lobe on which its stated albedo is tested (the rule of thumb for the
// central limit theorem); a lobe drawn 0 times passes an albedo of exactly 0.
inline constexpr long long kMinAlbedoDraws = 30;

// One lobe, measured over all draws.
struct DeltaLobeResult {
  long long count = 0;
  double share = 0, shareLower = 0, shareUpper = 1;  // Clopper–Pearson interval
  Eigen::ArrayXd albedo, albedoHalfWidth;            // per component; the t interval's half width
  DeltaExpectation expected;
  bool sharePassed = true, albedoPassed = true;
  // Why a stated albedo was not tested (too few draws of the lobe); empty when it was.
  std::string albedoUntested;
};

struct DeltaCheck {
  long long samples = 0;  // draws, delta or not
  long long deltaSamples = 0;
  double significance = 0;
  int components = 0;  // of the weights (the first delta sample's; others must match)
  std::optional<double> eta;
  double directionTolerance = 0;
  std::array<DeltaLobeResult, static_cast<int>(DeltaLobe::Count)> lobes{};
  long long wrongDirections = 0;  // delta samples in no accepted direction
  std::string wrongDirectionExample;
  Audit audit;  // non-finite or negative weights, non-finite or non-unit directions

  // Whether it ran (checkBsdf runs it only when there are delta samples or expectations).
  bool ran() const { return samples > 0; }
  bool passed() const;
  // Why a stated expectation could not be tested (DeltaLobeResult::albedoUntested); empty
  // when every one was.
  std::string inconclusiveReason() const;
  // "delta direction", "delta share", "delta albedo" and the audit's defects prefixed by
  // "delta " ("delta non-finite value"); empty when passed.
  std::vector<std::string> failures() const;
  std::string report() const;
};

// Draws `samples` times from model.sample at wi (local frame, unit) with streams of `seed`
// that the sampling test does not use, deterministic whatever the number of threads.
DeltaCheck checkDeltaLobes(const BsdfModel& model, const Eigen::Vector3d& wi,
                           const DeltaCheckOptions& options, long long samples, double significance,
                           uint64_t seed);

// The draws the delta lobes get beside the sampling test `test`: as many as it drew; but where
// a target sized it and its pdf claims nothing (a smooth glass: every sample a delta lobe, and
// the test draws only what meets a stray one), what the target needs of a histogram of the
// test's cells holding the whole mass, at most its budget.
long long deltaDraws(const TestResult& test);

}  // namespace verity::chi2
