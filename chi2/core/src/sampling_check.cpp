#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <verity/chi2/sampling_check.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <stdexcept>

namespace verity::chi2 {

uint64_t seedFromName(const std::string& name) {
  // 64-bit FNV-1a, the function the renderer's hashString (core/hash.h) computes too. This
  // library may depend on no other Verity code, and its users' checks fix their seeds by these
  // values, so it keeps its own five lines rather than share the renderer's.
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : name) h = (h ^ c) * 1099511628211ull;
  return h;
}

TestResult runSamplingTest(const Subject& subject, const TestOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  TestResult r;
  r.subject = subject.describe();
  if (!(options.significance > 0 && options.significance < 1))
    throw std::invalid_argument(fmt::format(
        "the per-test significance level must be in (0, 1), not {}", options.significance));
  if (options.samples < 1)
    throw std::invalid_argument(
        fmt::format("the number of samples must be at least 1, not {}", options.samples));
  r.significance = options.significance;
  r.samples = options.samples;
  // The density, guarded: non-finite or negative values are defects, and are replaced by
  // zero so that the quadrature still terminates.
  std::atomic<long long> badPdf{0}, negativePdf{0};
  std::mutex exampleMutex;
  std::string badExample;
  DensityFn pdf = [&](double x, double y) {
    const double v = subject.pdf(x, y);
    if (std::isfinite(v) && v >= 0) return v;
    (std::isfinite(v) ? negativePdf : badPdf)++;
    std::lock_guard lock(exampleMutex);
    if (badExample.empty())
      badExample = fmt::format("pdf() = {} at domain point ({}, {})", v, x, y);
    return 0.0;
  };
  const DensityFeatures features{[&](double x) { return subject.breakpointsY(x); },
                                 subject.breakpointsX(), subject.peaks()};
  // The cells, cut from the subject's domain before sampling: equal-probability cells
  // follow the claimed pdf (partition.h).
  r.domain = cellsFor(subject.domain(), options.cells, pdf, features, options.quadrature);
  const Domain& d = r.domain;
  const int cells = d.cells();

  // Sampling, in fixed chunks with one PCG32 stream each: the result does not depend on
  // the number of threads or their scheduling.
  constexpr long long kChunk = 1 << 16;
  const long long chunks = (options.samples + kChunk - 1) / kChunk;
  std::vector<std::vector<long long>> partial(chunks);
  std::vector<long long> validPerChunk(chunks, 0), outsidePerChunk(chunks, 0);
  std::vector<Audit> audits(chunks);
  tbb::parallel_for(0LL, chunks, [&](long long c) {
    pcg32 rng(options.seed, static_cast<uint64_t>(c));
    std::vector<long long> hist(cells, 0);
    const long long n = std::min(kChunk, options.samples - c * kChunk);
    for (long long k = 0; k < n; ++k) {
      const std::optional<Point2d> p = subject.sample(rng, audits[c]);
      if (!p) continue;
      ++validPerChunk[c];
      const int cell = d.cellOf(*p);
      if (cell < 0 || !d.inSupport(*p)) {
        ++outsidePerChunk[c];
        continue;
      }
      ++hist[cell];
    }
    partial[c] = std::move(hist);
  });
  r.observed.assign(cells, 0);
  for (long long c = 0; c < chunks; ++c) {
    for (int i = 0; i < cells; ++i) r.observed[i] += partial[c][i];
    r.valid += validPerChunk[c];
    r.outside += outsidePerChunk[c];
  }

  const std::vector<CellIntegral> integrals = integrateGrid(pdf, d, options.quadrature, features);
  r.probability.resize(cells);
  double total = 0;
  for (int i = 0; i < cells; ++i) {
    r.probability[i] = integrals[i].value;
    total += integrals[i].value;
    r.quadratureError += integrals[i].error;
  }

  for (const Audit& a : audits) r.audit.merge(a);
  if (badPdf) r.audit.record(Defect::NonFinite, badExample);
  if (negativePdf) r.audit.record(Defect::Negative, badExample);
  subject.extraChecks(r.audit);

  // Chi-square on the shape: given the number of valid samples, they are distributed
  // according to pdf / ∫pdf.
  r.expected.resize(cells);
  for (int i = 0; i < cells; ++i)
    r.expected[i] = total > 0 ? r.valid * r.probability[i] / total : 0.0;
  r.chiSquare = chiSquareTest(r.expected, r.observed, outrightThreshold(r.significance, cells));
  r.integral = checkIntegral(total, r.samples, r.valid, r.significance, options.integralTolerance);
  r.integralTolerance = options.integralTolerance;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
  if (valid == 0)
    return fmt::format(
        "no valid sample among {}: the sampler declined every one (or returned "
        "only delta lobes), so there was nothing to histogram",
        samples);
  if (chiSquare.degenerate)
    return fmt::format(
        "only {} cell(s) expect at least 5 of the {} valid samples after "
        "pooling: the chi-square test needs two",
        chiSquare.regularCells, valid);
  return {};
}

Verdict TestResult::verdict() const {
  if (!audit.clean() || outside > 0) return Verdict::Failed;
  if (!inconclusiveReason().empty()) return Verdict::Inconclusive;
  if (!chiSquarePassed() || !integral.passed) return Verdict::Failed;
  return Verdict::Passed;
}

std::string TestResult::report() const {
  std::string s = fmt::format("{}\n  domain {}, {} samples, significance {:.3g} (Sidak)\n", subject,
                              domain.name(), samples, significance);
  s += fmt::format("  [{}] {}\n", chiSquarePassed() ? "pass" : "FAIL", chiSquare.describe());
  if (outside > 0) s += fmt::format("         {} valid sample(s) outside the domain\n", outside);
  s += fmt::format("  [{}] {} (quadrature error estimate {:.2e})\n",
                   integral.passed ? "pass" : "FAIL", integral.describe(), quadratureError);
  s += fmt::format("  [{}] {}\n", audit.clean() ? "pass" : "FAIL", audit.describe());
  const std::string reason = inconclusiveReason();
  if (!reason.empty()) s += fmt::format("  inconclusive: {}\n", reason);
  s += fmt::format("  {} in {:.2f} s", verdictName(verdict()), seconds);
  return s;
}

}  // namespace verity::chi2
