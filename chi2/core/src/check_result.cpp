#include <fmt/format.h>
#include <fmt/ranges.h>
#include <verity/chi2/check_result.h>

#include <algorithm>

namespace verity::chi2 {

CheckResult runCheck(const Subject& subject, const CheckOptions& options,
                     const std::string& seedName) {
  TestOptions o;
  o.samples = options.samples;
  o.significance = options.significance;
  o.seed = options.seed ? *options.seed : seedFromName(seedName);
  o.cells = options.cells;
  o.power = options.power;
  o.detect = options.detect;
  o.maxSamples = options.maxSamples;
  o.auditedSamples = options.auditedSamples;
  o.progress = options.progress;
  CheckResult r;
  r.test = runSamplingTest(subject, o);
  return r;
}

Verdict CheckResult::verdict() const {
  if (delta.ran() && !delta.passed()) return Verdict::Failed;
  const Verdict v = test.verdict();
  if (v == Verdict::Passed && delta.ran() && !delta.inconclusiveReason().empty())
    return Verdict::Inconclusive;
  return v;
}

std::string CheckResult::inconclusiveReason() const {
  const std::string reason = test.inconclusiveReason();
  return reason.empty() && delta.ran() ? delta.inconclusiveReason() : reason;
}

std::vector<std::string> CheckResult::failures() const {
  std::vector<std::string> out;
  if (test.outside > 0) out.push_back("samples outside the domain");
  // An inconclusive test's statistics are the quadrature's, not the sampler's.
  if (test.verdict() == Verdict::Inconclusive) {
    out.push_back("inconclusive");
  } else {
    // Tests on expected counts that the quadrature could not vouch for did not run: a verdict
    // that fails on other grounds (a per-sample defect) does not list them.
    if (test.quadratureHolds()) {
      if (!test.chiSquare.passed(test.significance)) out.push_back("chi-square");
      if (!test.integral.passed) out.push_back("pdf integral");
    }
    if (verdict() == Verdict::Inconclusive) out.push_back("inconclusive");
  }
  for (int d = 0; d < static_cast<int>(Defect::Count); ++d)
    if (test.audit.count(static_cast<Defect>(d)) > 0)
      out.push_back(defectName(static_cast<Defect>(d)));
  if (delta.ran())
    for (const std::string& f : delta.failures()) out.push_back(f);
  return out;
}

bool CheckResult::failed(const std::string& check) const {
  const std::vector<std::string> f = failures();
  return std::find(f.begin(), f.end(), check) != f.end();
}

std::string CheckResult::report() const {
  std::string s = test.report();
  if (deltaSamples > 0)
    s += fmt::format("\n  {} delta-lobe samples (not histogrammed)", deltaSamples);
  if (delta.ran())
    s += fmt::format("\n{}\n  {} with the delta lobes{}", delta.report(), verdictName(verdict()),
                     verdict() == Verdict::Inconclusive ? ": " + inconclusiveReason() : "");
  if (!passed()) s += fmt::format("\n  failed: {}", fmt::join(failures(), ", "));
  return s;
}

}  // namespace verity::chi2
