// One sampling test: draw N samples, histogram them, integrate the claimed density over
// every cell, and run the checks — chi-square goodness of fit (the shape), the pdf
// integral against the valid fraction (the normalisation), and the per-sample audit.
#pragma once

#include <verity/chi2/audit.h>
#include <verity/chi2/chi_square.h>
#include <verity/chi2/integral_check.h>
#include <verity/chi2/partition.h>
#include <verity/chi2/phase_times.h>
#include <verity/chi2/power.h>
#include <verity/chi2/quadrature.h>
#include <verity/chi2/subject.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace verity::chi2 {

struct TestOptions {
  long long samples = 1'000'000;
  uint64_t seed = 1;
  // The per-test level, in (0, 1): the caller corrects for its own number of tests (e.g.
  // sidakLevel() in significance.h). runSamplingTest refuses any other value.
  double significance = 0;
  QuadratureOptions quadrature;
  double integralTolerance = kIntegralTolerance;
  // The cells the samples are histogrammed in, cut from the subject's domain (partition.h).
  // The grid by default: equal-probability cells made single tests 1.5-4 times slower
  // (Phong with exponent 10⁴: 10 times; docs/checks.md, "Cells that follow the density").
  CellLayout cells = CellLayout::Grid;
  // The probability at which the result states what the test could have caught.
  double power = kDefaultPower;
  // The caller's question. When set, `samples` is ignored: the test draws the samples the
  // target needs (from the cells' probabilities and the chi-square test's dof), at most
  // maxSamples; a target beyond that budget is never PASSED.
  std::optional<DetectionTarget> detect;
  long long maxSamples = 100'000'000;
  // The per-sample comparisons (weight against eval·|cos|/pdf, sample pdf against pdf(),
  // reciprocity: audit.h) on the first this many samples, rounded up to whole streams of
  // kSamplesPerStream; on every sample when unset. The result states what the subsample
  // could have met (TestResult::auditReach).
  std::optional<long long> auditedSamples;
  // Where the test has got to, updated as it runs, for a display (phase_times.h); none if null.
  CheckProgress* progress = nullptr;
};

// What a sampling test concluded. PASSED only when every check ran with the power it
// states; INCONCLUSIVE when a check could not run that way (its reason is named), so that a
// test never passes having checked nothing and never fails because of its own arithmetic.
enum class Verdict { Passed, Failed, Inconclusive };

std::string verdictName(Verdict verdict);  // "PASSED", "FAILED", "INCONCLUSIVE"

struct TestResult {
  std::string subject;
  Domain domain;  // the cells histogrammed in (TestOptions::cells of the subject's domain)
  double significance = 0;
  long long samples = 0, valid = 0;
  long long outside = 0;       // valid samples outside the domain's support: outright failures
  long long deltaSamples = 0;  // declined samples that were delta lobes (Subject::deltaSamples)
  std::vector<double> probability;  // ∫ pdf over each cell
  std::vector<double> expected;     // expected counts given the number of valid samples
  std::vector<long long> observed;
  double quadratureError = 0;  // summed Gauss–Kronrod error estimates
  ChiSquareResult chiSquare;
  IntegralCheck integral;
  Audit audit;
  double seconds = 0;  // the whole test, as the report's last line says
  // Its phases. Drawing, audit and binning run together over the threads: their wall-clock
  // time is shared out in proportion to the thread-seconds each took. The caller adds the
  // delta lobes' and the figure's.
  PhaseTimes phases;

  double integralTolerance = 0;  // the stated quadrature tolerance on ∫pdf
  // Delta-lobe samples were drawn and checked apart (delta_check.h): with no valid sample
  // there is nothing to histogram, yet something was checked.
  bool deltaLobesChecked = false;

  // What the two statistical tests could have caught at their level (see power.h).
  ChiSquarePower chiSquarePower;
  IntegralPower integralPower;
  // The caller's target, and the samples it needs (above maxSamples: not reached).
  std::optional<DetectionTarget> target;
  long long neededSamples = 0, maxSamples = 0;
  bool targetReached() const { return !target || neededSamples <= maxSamples; }
  // The samples whose per-sample comparisons ran (all of them unless
  // TestOptions::auditedSamples chose fewer), and the least fraction of the samples a defect
  // of theirs must touch to be met among them with probability auditPower (TestOptions::power):
  // 1 − (1 − power)^(1/n).
  long long auditedSamples = 0;
  double auditReach = 0, auditPower = 0;
  bool auditedAll() const { return auditedSamples >= samples; }
  // The claimed pdf integrates to zero over every cell (every sample a delta lobe, or none).
  bool nothingClaimed() const;

  // The chi-square test ran when there were valid samples, at least two cells after pooling
  // and trustworthy expected counts; otherwise no statistic of it is shown.
  bool chiSquareRan() const { return valid > 0 && !chiSquare.degenerate && quadratureHolds(); }

  bool chiSquarePassed() const { return outside == 0 && chiSquare.passed(significance); }
  // The cell probabilities are as accurate as the integral check states: the summed error
  // estimate lies within its tolerance. Otherwise the expected counts, the pdf integral and
  // every verdict drawn from them are the quadrature's, not the sampler's.
  bool quadratureHolds() const { return quadratureError <= integralTolerance; }
  // FAILED on a defect that needs no quadrature (a per-sample defect, a sample outside the
  // support); else INCONCLUSIVE when the quadrature does not hold; else FAILED on the
  // chi-square or pdf-integral test; else INCONCLUSIVE when too few cells expect enough
  // samples for the chi-square test, or when the caller's target needed more samples than
  // the budget; else PASSED. A sampler that declines every sample while its pdf integrates
  // to zero is PASSED on the pdf-integral test alone: it claims nothing, and draws nothing;
  // one whose samples were all delta lobes is INCONCLUSIVE unless they were checked apart.
  Verdict verdict() const;
  // Why the verdict is INCONCLUSIVE; empty otherwise.
  std::string inconclusiveReason() const;
  bool passed() const { return verdict() == Verdict::Passed; }
  std::string report() const;
};

// The samples a chi-square test on cells of these probabilities (summing to `total`, the
// claimed ∫pdf) draws to find `target` at `level`.
long long samplesForTarget(const DetectionTarget& target, const std::vector<double>& probability,
                           double total, double level);

TestResult runSamplingTest(const Subject& subject, const TestOptions& options);

// A fixed seed derived from a configuration's name (FNV-1a), so that every configuration
// has its own reproducible stream and no seed is ever picked by hand.
uint64_t seedFromName(const std::string& name);

}  // namespace verity::chi2
