#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <verity/chi2/cell_locator.h>
#include <verity/chi2/partition.h>
#include <verity/chi2/sampling_check.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

namespace verity::chi2 {

uint64_t seedFromName(const std::string& name) {
  // 64-bit FNV-1a, the function the renderer's hashString (core/hash.h) computes too. This
  // library may depend on no renderer code, and its users' checks fix their seeds by these
  // values, so it keeps its own five lines rather than share the renderer's.
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : name) h = (h ^ c) * 1099511628211ull;
  return h;
}

// N·w² must reach the noncentrality of the test's dof, and the dof depends on how many cells
// expect five samples, so the two are iterated to a fixed point (a few steps: the dof only
// grows with N).
long long samplesForTarget(const DetectionTarget& target, const std::vector<double>& probability,
                           double total, double level) {
  const double w2 = std::pow(effectForDensityError(target.densityError, target.mass), 2);
  std::vector<double> expected(probability.size());
  int dof = std::max(1, static_cast<int>(probability.size()) - 1);
  double valid = 0;
  for (int step = 0; step < 16; ++step) {
    valid = chiSquareNoncentrality(dof, level, target.power) / w2;
    for (size_t i = 0; i < probability.size(); ++i) expected[i] = valid * probability[i] / total;
    const int planned = std::max(1, plannedDof(expected));
    if (planned == dof) break;
    dof = planned;
  }
  // Valid samples are a fraction ∫pdf of those drawn.
  const double drawn = std::ceil(valid / std::min(1.0, total));
  return drawn >= 9e18 ? std::numeric_limits<long long>::max() : static_cast<long long>(drawn);
}

namespace {

void validate(const TestOptions& options) {
  if (!(options.significance > 0 && options.significance < 1))
    throw std::invalid_argument(fmt::format(
        "the per-test significance level must be in (0, 1), not {}", options.significance));
  if (!(options.power > options.significance && options.power < 1))
    throw std::invalid_argument(fmt::format("the power must be in (level, 1) = ({}, 1), not {}",
                                            options.significance, options.power));
  if (options.detect) {
    validate(*options.detect);
    if (options.maxSamples < 1)
      throw std::invalid_argument(
          fmt::format("the sample budget must be at least 1, not {}", options.maxSamples));
  } else if (options.samples < 1) {
    throw std::invalid_argument(
        fmt::format("the number of samples must be at least 1, not {}", options.samples));
  }
  if (options.auditedSamples && *options.auditedSamples < 1)
    throw std::invalid_argument(
        fmt::format("the samples to audit must be at least 1, not {}", *options.auditedSamples));
}

}  // namespace

TestResult runSamplingTest(const Subject& subject, const TestOptions& options) {
  const PhaseClock start;
  validate(options);
  TestResult r;
  r.subject = subject.describe();
  r.significance = options.significance;
  r.integralTolerance = options.integralTolerance;

  // The claimed density over every cell first: a caller's target sizes the sample count from
  // it. Non-finite or negative values are defects, and are replaced by zero so that the
  // quadrature still terminates.
  // Each kind's example is its bad value at the least point (x, then y), whichever thread
  // meets it first, so that the report is the same for any number of threads.
  struct BadValues {
    long long count = 0;
    std::optional<Point2d> at;
    double value = 0;
  };
  std::mutex badMutex;
  BadValues nonFinite, negative;
  auto checked = [&](double v, double x, double y) {
    if (std::isfinite(v) && v >= 0) return v;
    std::lock_guard lock(badMutex);
    BadValues& bad = std::isfinite(v) ? negative : nonFinite;
    ++bad.count;
    if (!bad.at || std::pair(x, y) < std::pair(bad.at->x(), bad.at->y())) {
      bad.at = Point2d(x, y);
      bad.value = v;
    }
    return 0.0;
  };
  const DensityFeatures features{[&](double x) { return subject.breakpointsY(x); },
                                 subject.breakpointsX(), subject.peaks(),
                                 [&](double y) { return subject.breakpointCrossingsX(y); }};
  // The cells, cut from the subject's domain (equal-probability cells follow the claimed pdf:
  // partition.h), and the claimed density over each; through batches of points where the
  // subject evaluates its density so, with the same figures (DensityBatchFn).
  std::vector<CellIntegral> integrals;
  auto reached = [&](Phase phase) {
    if (options.progress) options.progress->phase = phase;
  };
  auto cellsAndIntegrals = [&](const auto& pdf) {
    reached(Phase::Cells);
    {
      const PhaseTimer timer(r.phases, Phase::Cells);
      r.domain = cellsFor(subject.domain(), options.cells, pdf, features, options.quadrature);
    }
    reached(Phase::Quadrature);
    const PhaseTimer timer(r.phases, Phase::Quadrature);
    integrals = integrateGrid(pdf, r.domain, options.quadrature, features);
  };
  if (subject.batchedPdf())
    cellsAndIntegrals(
        DensityBatchFn([&](const std::vector<Point2d>& points, std::vector<double>& values) {
          subject.pdfBatch(points, values);
          for (size_t k = 0; k < points.size(); ++k)
            values[k] = checked(values[k], points[k].x(), points[k].y());
        }));
  else
    cellsAndIntegrals(
        DensityFn([&](double x, double y) { return checked(subject.pdf(x, y), x, y); }));
  const Domain& d = r.domain;
  const int cells = d.cells();
  r.probability.resize(cells);
  double total = 0;
  for (int i = 0; i < cells; ++i) {
    r.probability[i] = integrals[i].value;
    total += integrals[i].value;
    r.quadratureError += integrals[i].error;
  }

  r.samples = options.samples;
  if (options.detect && total > 0) {
    r.target = options.detect;
    r.maxSamples = options.maxSamples;
    r.neededSamples = samplesForTarget(*options.detect, r.probability, total, r.significance);
    r.samples = std::min(r.neededSamples, options.maxSamples);
  } else if (options.detect) {
    // Nothing is claimed, so a single valid sample fails the test outright: draw enough to
    // meet, with the target's power, a sampler that returns one with the probability the
    // target's error moves, εm: (1 − εm)^N ≤ 1 − power. (Drawing the whole budget cost a
    // smooth glass 10⁸ draws to say no more.)
    r.target = options.detect;
    r.maxSamples = options.maxSamples;
    r.neededSamples = static_cast<long long>(
        std::ceil(std::log1p(-options.detect->power) /
                  std::log1p(-options.detect->densityError * options.detect->mass)));
    r.samples = std::min(r.neededSamples, options.maxSamples);
  }

  // Sampling, in fixed chunks with one PCG32 stream each: the result does not depend on
  // the number of threads or their scheduling.
  const long long deltaBefore = subject.deltaSamples();
  constexpr long long kChunk = kSamplesPerStream;
  const long long chunks = (r.samples + kChunk - 1) / kChunk;
  // Whole streams are audited, so that the audited samples do not depend on the threads.
  const auto auditsChunk = [&](long long chunk) {
    return !options.auditedSamples || chunk * kChunk < *options.auditedSamples;
  };
  std::vector<std::vector<long long>> partial(chunks);
  std::vector<long long> validPerChunk(chunks, 0), outsidePerChunk(chunks, 0);
  std::vector<Audit> audits(chunks);
  std::vector<double> drawSeconds(chunks), binSeconds(chunks);
  const PhaseClock samplingClock;
  reached(Phase::Drawing);
  if (options.progress) {
    options.progress->samples = r.samples;
    options.progress->drawn = 0;  // a run of several checks shares one progress
  }
  const CellLocator locator(d);
  tbb::parallel_for(0LL, chunks, [&](long long c) {
    const PhaseClock drawClock;
    pcg32 rng(options.seed, static_cast<uint64_t>(c));
    std::vector<long long> hist(cells, 0);
    std::vector<std::optional<Point2d>> points(std::min(kChunk, r.samples - c * kChunk));
    audits[c].setComparesSamples(auditsChunk(c));
    subject.sampleBatch(rng, points, audits[c]);
    drawSeconds[c] = drawClock.seconds();
    if (options.progress) options.progress->drawn += static_cast<long long>(points.size());
    const PhaseClock binClock;
    // Counted in locals: the per-block vectors share cache lines between the threads.
    long long valid = 0, outside = 0;
    for (const std::optional<Point2d>& p : points) {
      if (!p) continue;
      ++valid;
      const int cell = locator.cellOf(*p);
      if (cell < 0 || !d.inSupport(*p)) {
        ++outside;
        continue;
      }
      ++hist[cell];
    }
    validPerChunk[c] = valid;
    outsidePerChunk[c] = outside;
    partial[c] = std::move(hist);
    binSeconds[c] = binClock.seconds();
  });
  const double samplingSeconds = samplingClock.seconds();
  r.observed.assign(cells, 0);
  double drawn = 0, binned = 0;
  for (long long c = 0; c < chunks; ++c) {
    for (int i = 0; i < cells; ++i) r.observed[i] += partial[c][i];
    r.valid += validPerChunk[c];
    r.outside += outsidePerChunk[c];
    drawn += drawSeconds[c];
    binned += binSeconds[c];
    if (auditsChunk(c)) r.auditedSamples += std::min(kChunk, r.samples - c * kChunk);
  }
  r.auditPower = options.power;
  r.auditReach =
      r.auditedSamples > 0 ? -std::expm1(std::log1p(-options.power) / r.auditedSamples) : 1.0;

  r.deltaSamples = subject.deltaSamples() - deltaBefore;
  for (const Audit& a : audits) r.audit.merge(a);
  // The sampling's wall-clock time shared out by thread-seconds: the subject's sampleBatch
  // times its own audit (Audit::addSeconds), the rest of it is drawing.
  const double audited = std::min(r.audit.seconds(), drawn);
  if (drawn + binned > 0) {
    const double share = samplingSeconds / (drawn + binned);
    r.phases.add(Phase::Drawing, (drawn - audited) * share);
    r.phases.add(Phase::Audit, audited * share);
    r.phases.add(Phase::Binning, binned * share);
  }
  for (const auto& [defect, bad] :
       {std::pair(Defect::NonFinite, &nonFinite), std::pair(Defect::Negative, &negative)})
    if (bad->count > 0)
      r.audit.record(defect, fmt::format("pdf() = {} at domain point ({}, {})", bad->value,
                                         bad->at->x(), bad->at->y()));
  {
    reached(Phase::Audit);
    const PhaseTimer timer(r.phases, Phase::Audit);
    subject.extraChecks(r.audit);
  }
  reached(Phase::Statistics);
  const PhaseClock statistics;
  // Chi-square on the shape: given the number of valid samples, they are distributed
  // according to pdf / ∫pdf.
  r.expected.resize(cells);
  for (int i = 0; i < cells; ++i)
    r.expected[i] = total > 0 ? r.valid * r.probability[i] / total : 0.0;
  r.chiSquare = chiSquareTest(r.expected, r.observed, outrightThreshold(r.significance, cells));
  r.integral = checkIntegral(total, r.samples, r.valid, r.significance, options.integralTolerance);
  if (r.chiSquareRan())
    r.chiSquarePower = chiSquarePower(r.chiSquare.dof, static_cast<double>(r.valid), r.significance,
                                      options.power);
  r.integralPower =
      integralPower(total, r.samples, r.significance, options.integralTolerance, options.power);
  r.phases.add(Phase::Statistics, statistics.seconds());
  reached(Phase::Count);
  r.seconds = start.seconds();
  return r;
}

std::string verdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::Passed:
      return "PASSED";
    case Verdict::Failed:
      return "FAILED";
    case Verdict::Inconclusive:
      return "INCONCLUSIVE";
  }
  return "?";
}

std::string TestResult::inconclusiveReason() const {
  if (!audit.clean() || outside > 0) return {};
  if (!quadratureHolds())
    return fmt::format(
        "the quadrature's error estimate {:.2e} exceeds the stated tolerance {:.1e}, so the "
        "expected counts and the pdf integral cannot be trusted",
        quadratureError, integralTolerance);
  if (!chiSquarePassed() || !integral.passed) return {};
  std::string reason;
  if (valid == 0 && deltaSamples > 0 && !deltaLobesChecked)
    reason = fmt::format(
        "no valid sample among {}: {} were delta lobes, which the histogram cannot test{}", samples,
        deltaSamples, deltaSamples < samples ? ", and the others were declined" : "");
  if (valid > 0 && chiSquare.degenerate)
    reason = fmt::format(
        "only {} cell(s) expect at least 5 of the {} valid samples after "
        "pooling: the chi-square test needs two",
        chiSquare.regularCells, valid);
  if (!targetReached())
    reason +=
        fmt::format("{}finding {} needs {} samples, more than the budget of {}",
                    reason.empty() ? "" : "; ", target->describe(), neededSamples, maxSamples);
  return reason;
}

Verdict TestResult::verdict() const {
  if (!audit.clean() || outside > 0) return Verdict::Failed;
  if (!inconclusiveReason().empty()) return Verdict::Inconclusive;
  if (!chiSquarePassed() || !integral.passed) return Verdict::Failed;
  return Verdict::Passed;
}

bool TestResult::nothingClaimed() const {
  return std::all_of(probability.begin(), probability.end(), [](double p) { return p == 0; });
}

std::string TestResult::report() const {
  std::string s = fmt::format("{}\n  domain {}, {} samples", subject, domain.name(), samples);
  if (target && nothingClaimed())
    s += fmt::format(
        " ({} to meet with {:.0f}% probability a sampler that returns a sample "
        "with probability {:.2g} where pdf() claims none{})",
        targetReached() ? "chosen" : "the budget", 100 * target->power,
        target->densityError * target->mass,
        targetReached() ? "" : fmt::format(", which needs {}", neededSamples));
  else if (target)
    s += fmt::format(" ({} to find {}{})", targetReached() ? "chosen" : "the budget",
                     target->describe(),
                     targetReached() ? "" : fmt::format(", which needs {}", neededSamples));
  s += fmt::format(", level {:.3g} per test\n", significance);
  const std::string indent = "         ";
  // A statistic is shown only for a test that ran: an inconclusive run's expected counts are
  // the quadrature's, and a degenerate histogram has no statistic.
  if (chiSquareRan()) {
    s += fmt::format("  [{}] {}\n", chiSquarePassed() ? "pass" : "FAIL", chiSquare.describe());
    s += indent + "could have caught: " + chiSquarePower.describe() + "\n";
  } else if (chiSquare.outrightSamples > 0 && quadratureHolds()) {
    s += fmt::format("  [FAIL] {}\n", chiSquare.describe());
  } else {
    s += fmt::format("  [ -- ] chi-square: not run ({})\n",
                     valid == 0           ? "no valid sample to histogram"
                     : !quadratureHolds() ? "the expected counts are not trustworthy"
                                          : "fewer than two cells expect 5 samples");
  }
  if (outside > 0) s += indent + fmt::format("{} valid sample(s) outside the domain\n", outside);
  if (quadratureHolds()) {
    s += fmt::format("  [{}] {} (quadrature error estimate {:.2e})\n",
                     integral.passed ? "pass" : "FAIL", integral.describe(), quadratureError);
    s += indent + "could have caught: " + integralPower.describe() + "\n";
  } else {
    s += fmt::format("  [ -- ] pdf integral: not run (quadrature error estimate {:.2e})\n",
                     quadratureError);
  }
  s += fmt::format("  [{}] {}\n", audit.clean() ? "pass" : "FAIL", audit.describe());
  if (!auditedAll())
    s += indent + fmt::format(
                      "compared per sample: the first {} of the {} samples, where a "
                      "defect touching {:.2g} of the samples or more would have been "
                      "met with {:.0f}% probability\n",
                      auditedSamples, samples, auditReach, 100 * auditPower);
  const Verdict v = verdict();
  // Every sample a delta lobe: the verdict is the delta lobes' (below), not this part's.
  if (v == Verdict::Passed && !chiSquareRan() && deltaLobesChecked)
    return s + fmt::format(
                   "  histogram: nothing to test in {:.2f} s, every sample was a delta "
                   "lobe (checked below)",
                   seconds);
  s += fmt::format("  {} in {:.2f} s", verdictName(v), seconds);
  if (v == Verdict::Inconclusive) s += ": " + inconclusiveReason();
  if (v == Verdict::Passed)
    s += ": " + (chiSquareRan() ? chiSquarePower.describe()
                                : "the sampler declined every sample and pdf() claims no "
                                  "mass; " +
                                      integralPower.describe());
  return s;
}

}  // namespace verity::chi2
