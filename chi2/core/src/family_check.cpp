#include <fmt/format.h>
#include <fmt/ranges.h>
#include <verity/chi2/family_check.h>
#include <verity/chi2/significance.h>
#include <verity/stats/junit.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <numeric>
#include <pcg_random.hpp>
#include <stdexcept>

namespace verity::chi2 {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("checkBsdfFamily: " + what);
}

void validate(const std::vector<FamilyParameter>& parameters, const FamilyOptions& options) {
  require(!parameters.empty(), "no parameter: a family needs at least one");
  for (const FamilyParameter& p : parameters) {
    require(!p.name.empty(), "every parameter needs a name");
    // A second range for one name would be a box of which the factory sees one side.
    require(std::count_if(parameters.begin(), parameters.end(),
                          [&](const FamilyParameter& q) { return q.name == p.name; }) == 1,
            fmt::format("parameter {} is given more than once", p.name));
    require(std::isfinite(p.lo) && std::isfinite(p.hi) && p.lo <= p.hi,
            fmt::format("parameter {}: its range [{}, {}] must be finite with lo <= hi", p.name,
                        p.lo, p.hi));
    require(!p.logarithmic || p.lo > 0,
            fmt::format("parameter {}: a logarithmic range needs lo > 0 (it is {})", p.name, p.lo));
  }
  // 2^d corners: more than 2^20 is no family anyone runs.
  require(parameters.size() <= 20,
          fmt::format("{} parameters: at most 20 (2^d corners)", parameters.size()));
  require(!options.incidences.empty(), "FamilyOptions::incidences is empty");
  for (double t : options.incidences)
    require(t >= 0 && t <= 90,
            fmt::format("FamilyOptions::incidences: {} is not an angle in [0, 90] degrees", t));
  require(options.interiorPoints >= 0,
          fmt::format("FamilyOptions::interiorPoints = {} must be >= 0", options.interiorPoints));
  require(options.level > 0 && options.level < 1,
          fmt::format("FamilyOptions::level = {} must be in (0, 1)", options.level));
}

// A point of the box from its coordinates u in [0, 1]^d.
std::vector<double> valuesAt(const std::vector<FamilyParameter>& parameters,
                             const std::vector<double>& u) {
  std::vector<double> v(parameters.size());
  for (size_t i = 0; i < parameters.size(); ++i) {
    const FamilyParameter& p = parameters[i];
    v[i] = p.logarithmic ? std::exp(std::log(p.lo) + u[i] * (std::log(p.hi) - std::log(p.lo)))
                         : p.lo + u[i] * (p.hi - p.lo);
  }
  return v;
}

// n points of a Latin hypercube in [0, 1]^d (McKay, Beckman and Conover 1979, "A comparison of
// three methods for selecting values of input variables"): each coordinate's n strata hold one
// point each, at a uniform position inside its stratum.
std::vector<std::vector<double>> latinHypercube(int n, size_t d, uint64_t seed) {
  pcg32 rng(seed);
  std::vector<std::vector<double>> points(n, std::vector<double>(d));
  std::vector<int> strata(n);
  for (size_t j = 0; j < d; ++j) {
    std::iota(strata.begin(), strata.end(), 0);
    for (int k = n - 1; k > 0; --k) std::swap(strata[k], strata[rng(uint32_t(k + 1))]);
    for (int k = 0; k < n; ++k) points[k][j] = (strata[k] + std::ldexp(double(rng()), -32)) / n;
  }
  return points;
}

std::string configurationName(const std::vector<FamilyParameter>& parameters,
                              const std::vector<double>& values, double incidence, bool below) {
  std::string s;
  for (size_t i = 0; i < parameters.size(); ++i)
    s += fmt::format("{}{}={:.6g}", i ? " " : "", parameters[i].name, values[i]);
  return s + fmt::format(" at {:g}° from {}", incidence, below ? "below" : "above");
}

// The worst per-sample defect: a comparison beyond what rounding the directions gives where
// there is one, else the comparison furthest from its reference (within rounding), else
// the first defect's first example.
std::string worstDefect(const Audit& audit) {
  std::string out;
  double worst = -1;
  bool beyond = false;
  for (int d = 0; d < static_cast<int>(Defect::Count); ++d) {
    const Defect defect = static_cast<Defect>(d);
    if (audit.count(defect) == 0) continue;
    if (audit.worstExample(defect).empty()) {  // not a comparison
      if (out.empty()) out = fmt::format("{}: {}", defectName(defect), audit.example(defect));
      continue;
    }
    const bool b = audit.beyondRounding(defect) > 0;
    const double w = b ? audit.worstBeyondRounding(defect) : audit.worst(defect);
    if (std::make_pair(b, w) > std::make_pair(beyond, worst) || out.empty()) {
      beyond = b;
      worst = w;
      out = fmt::format("{} {} (|ratio - 1| {:.3g}): {}", defectName(defect),
                        b ? "beyond rounding" : "within rounding", w,
                        b ? audit.worstBeyondRoundingExample(defect) : audit.worstExample(defect));
    }
  }
  return out;
}

// A configuration that failed on per-sample comparisons alone, each within what rounding the
// directions give there.
bool failedOnlyByRounding(const CheckResult& c) {
  if (c.verdict() != Verdict::Failed || !c.test.audit.onlyRounding()) return false;
  for (const std::string& f : c.failures())
    if (f != defectName(Defect::Weight) && f != defectName(Defect::SamplePdf) &&
        f != defectName(Defect::Reciprocity))
      return false;
  return true;
}

// The configurations in the report's order: failed, inconclusive, passed; each group in the
// family's order.
std::vector<size_t> reportOrder(const FamilyResult& r) {
  std::vector<size_t> order;
  for (Verdict v : {Verdict::Failed, Verdict::Inconclusive, Verdict::Passed})
    for (size_t i = 0; i < r.configurations.size(); ++i)
      if (r.verdictOf(i) == v) order.push_back(i);
  return order;
}

// What failed, or why the check could not run (`inconclusiveReason`); "" when it passed. A
// CheckResult or a StochasticCheck.
template <class Check>
std::string whatFailed(const Check& c, const std::string& inconclusiveReason) {
  if (c.verdict() == Verdict::Inconclusive) return inconclusiveReason;
  return c.passed() ? "" : fmt::format("{}", fmt::join(c.failures(), ", "));
}

// One row's facts, shared by the text, Markdown and JSON forms.
struct Row {
  std::string verdict, configuration, failed, statistic, defect, caught;
};

// "FAILED (rounding)" for a configuration that failed only within rounding.
std::string verdictText(const FamilyResult& r, size_t i) {
  const Verdict v = r.verdictOf(i);
  return !r.stochastic() && failedOnlyByRounding(r.results[i])
             ? fmt::format("{} (rounding)", verdictName(v))
             : verdictName(v);
}

Row rowOf(const FamilyResult& r, size_t i) {
  Row row;
  row.verdict = verdictText(r, i);
  row.configuration = r.configurations[i].name;
  if (r.stochastic()) {
    const StochasticCheck& c = r.stochasticResults[i];
    row.failed = whatFailed(c, c.inconclusiveReason());
    if (c.verdict() != Verdict::Inconclusive) {  // else no test ran
      double totalP = 1;
      for (const WelchComparison& w : c.total) totalP = std::min(totalP, w.p);
      row.statistic = fmt::format("albedo: smallest p = {:.3g}; cells: {} of {} rejected (Holm)",
                                  totalP, c.rejections, c.cellTests.size());
    }
    row.defect = worstDefect(c.audit);
    if (std::isfinite(c.detectableTotal) && std::isfinite(c.detectableCell))
      row.caught = fmt::format("{:.2g}% of the albedo, {:.2g}% of one cell's",
                               100 * c.detectableTotal, 100 * c.detectableCell);
    return row;
  }
  const CheckResult& c = r.results[i];
  const TestResult& t = c.test;
  row.failed = whatFailed(c, c.inconclusiveReason());
  if (t.chiSquareRan()) {
    row.statistic = fmt::format("chi-square {:.4g} on {} dof, p = {:.3g}", t.chiSquare.statistic,
                                t.chiSquare.dof, t.chiSquare.pValue);
    // A failure that no statistic shows: a sample where the claimed density is zero.
    if (t.chiSquare.outrightSamples > 0)
      row.statistic += fmt::format(
          "; {} sample(s) where the density is zero (cell {} expects {:.3g})",
          t.chiSquare.outrightSamples, t.chiSquare.outrightCell, t.chiSquare.outrightExpected);
  }
  row.defect = worstDefect(t.audit);
  if (t.chiSquarePower.ran())
    row.caught = fmt::format("{:.2g}% over 1/4 of the mass",
                             100 * t.chiSquarePower.densityError(kStatedMass));
  return row;
}

std::string summary(const FamilyResult& r) {
  std::string params;
  for (const FamilyParameter& p : r.parameters)
    params += fmt::format("{}{} in [{:g}, {:g}]{}", params.empty() ? "" : ", ", p.name, p.lo, p.hi,
                          p.logarithmic ? " (log)" : "");
  return fmt::format(
      "BSDF family of {}{}: {} configurations, {} statistical tests at a family-wise level of {:g} "
      "(Sidak: {:.3g} per test); {} passed, {} failed ({} of them only within rounding), {} "
      "inconclusive: {}",
      params, r.stochastic() ? " in the mean-weight mode" : "", r.configurations.size(),
      r.statisticalTests, r.level, r.perTestLevel, r.count(Verdict::Passed),
      r.count(Verdict::Failed), r.failedOnlyByRounding(), r.count(Verdict::Inconclusive),
      verdictName(r.verdict()));
}

}  // namespace

BsdfCheckOptions FamilyOptions::defaultCheck() {
  BsdfCheckOptions o;
  o.detect = DetectionTarget{0.02, kStatedMass, kDefaultPower};
  return o;
}

Eigen::Vector3d FamilyConfiguration::wi() const {
  // In single precision, unit there: a BSDF in float sees exactly the direction whose
  // geometry (its mirror and refraction peaks, where refraction ends) the check computes. From
  // the double direction it saw one 3·10⁻⁸ away, enough to move a refraction lobe of width 10⁻⁶
  // (α 10⁻⁴, η 1.01) or the edge of one that ends with a jump (α 4, η 1.01).
  const double t = incidence * std::numbers::pi / 180;
  const Eigen::Vector3f w(float(std::sin(t)), 0, float(below ? -std::cos(t) : std::cos(t)));
  return w.normalized().cast<double>();
}

std::vector<FamilyConfiguration> familyConfigurations(
    const std::vector<FamilyParameter>& parameters, const FamilyOptions& options) {
  validate(parameters, options);
  const size_t d = parameters.size();
  std::vector<std::pair<std::vector<double>, bool>> points;
  // Corner k takes parameter j's upper end where bit j of k is set. A parameter of one value
  // (lo = hi) gives its corners twice: they are kept once.
  for (uint64_t k = 0; k < (uint64_t(1) << d); ++k) {
    std::vector<double> v(d);
    for (size_t j = 0; j < d; ++j) v[j] = (k >> j) & 1 ? parameters[j].hi : parameters[j].lo;
    if (std::none_of(points.begin(), points.end(), [&](const auto& p) { return p.first == v; }))
      points.emplace_back(std::move(v), true);
  }
  for (const std::vector<double>& u : latinHypercube(options.interiorPoints, d, options.seed))
    points.emplace_back(valuesAt(parameters, u), false);
  std::vector<FamilyConfiguration> out;
  for (const auto& [values, corner] : points)
    for (bool below : {false, true}) {
      if (below && !options.fromBelow) continue;
      for (double t : options.incidences) {
        FamilyConfiguration c;
        c.values = values;
        c.corner = corner;
        c.incidence = t;
        c.below = below;
        c.name = configurationName(parameters, values, t, below);
        out.push_back(std::move(c));
      }
    }
  return out;
}

FamilyResult checkBsdfFamily(const BsdfFamily& family,
                             const std::vector<FamilyParameter>& parameters,
                             const FamilyOptions& options) {
  FamilyResult r;
  r.parameters = parameters;
  r.configurations = familyConfigurations(parameters, options);
  r.level = options.level;
  if (CheckProgress* p = options.check.progress)
    p->checks = static_cast<long long>(r.configurations.size());
  // Every configuration's model and options first: each configuration's options may state
  // tests of their own (the delta lobes' expectations), and Šidák's share of the level
  // follows from the count of all of them.
  std::vector<BsdfModel> models;
  std::vector<BsdfCheckOptions> checks;
  r.statisticalTests = 0;
  for (const FamilyConfiguration& c : r.configurations) {
    models.push_back(family(c.values));
    if (options.stochastic) {
      r.statisticalTests += kStatisticalTestsPerStochasticCheck;
      continue;
    }
    BsdfCheckOptions check = options.check;
    check.name = c.name;
    const BsdfModel& model = models.back();
    if (!check.delta.eta && model.relativeIndex() != 1) check.delta.eta = model.relativeIndex();
    if (options.configure) options.configure(c, model, check);
    r.statisticalTests += kStatisticalTestsPerCheck + check.delta.statisticalTests();
    checks.push_back(std::move(check));
  }
  r.perTestLevel = sidakLevel(options.level, r.statisticalTests);
  for (size_t i = 0; i < r.configurations.size(); ++i) {
    const FamilyConfiguration& c = r.configurations[i];
    if (CheckProgress* p = options.check.progress) ++p->check;
    if (options.stochastic) {
      StochasticCheckOptions check = options.stochasticCheck;
      check.name = c.name;
      check.significance = r.perTestLevel;
      r.stochasticResults.push_back(checkStochasticBsdf(models[i], c.wi(), check));
      continue;
    }
    checks[i].significance = r.perTestLevel;
    r.results.push_back(checkBsdf(models[i], c.wi(), checks[i]));
  }
  return r;
}

Verdict FamilyResult::verdictOf(size_t configuration) const {
  return stochastic() ? stochasticResults.at(configuration).verdict()
                      : results.at(configuration).verdict();
}

int FamilyResult::failedOnlyByRounding() const {
  return static_cast<int>(std::count_if(results.begin(), results.end(), [](const CheckResult& c) {
    return chi2::failedOnlyByRounding(c);
  }));
}

int FamilyResult::count(Verdict verdict) const {
  int n = 0;
  for (size_t i = 0; i < configurations.size(); ++i) n += verdictOf(i) == verdict;
  return n;
}

Verdict FamilyResult::verdict() const {
  if (count(Verdict::Failed) > 0) return Verdict::Failed;
  if (count(Verdict::Inconclusive) > 0) return Verdict::Inconclusive;
  return Verdict::Passed;
}

std::string FamilyResult::report() const {
  std::string s = summary(*this) + "\n";
  for (size_t i : reportOrder(*this)) {
    const Row row = rowOf(*this, i);
    s += fmt::format("  {:<12} {}", row.verdict, row.configuration);
    if (!row.failed.empty()) s += "\n      " + row.failed;
    const bool passed = verdictOf(i) == Verdict::Passed;
    if (!row.statistic.empty() && !passed) s += "\n      " + row.statistic;
    if (!row.defect.empty()) s += "\n      worst per-sample defect: " + row.defect;
    if (passed && !row.caught.empty()) s += ": could have caught " + row.caught;
    s += "\n";
  }
  return s;
}

std::string FamilyResult::markdown() const {
  std::string s = summary(*this) + "\n\n";
  s += "| verdict | configuration | what failed, or why it could not run | statistic | worst "
       "per-sample defect | what it could have caught |\n|---|---|---|---|---|---|\n";
  auto cell = [](std::string text) {
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : c == '\n' ? " " : std::string(1, c);
    return out;
  };
  for (size_t i : reportOrder(*this)) {
    const Row row = rowOf(*this, i);
    s += fmt::format("| {} | {} | {} | {} | {} | {} |\n", row.verdict, cell(row.configuration),
                     cell(row.failed), cell(row.statistic), cell(row.defect), row.caught);
  }
  return s;
}

std::string FamilyResult::junit(const std::string& suite) const {
  std::vector<stats::JunitCase> cases;
  for (size_t i = 0; i < configurations.size(); ++i) {
    stats::JunitCase j;
    j.name = configurations[i].name;
    const Verdict v = verdictOf(i);
    j.type = verdictName(v);
    // FAILED is a failure; INCONCLUSIVE an error, never shown as passed.
    j.outcome = v == Verdict::Passed   ? stats::JunitCase::Outcome::Passed
                : v == Verdict::Failed ? stats::JunitCase::Outcome::Failure
                                       : stats::JunitCase::Outcome::Error;
    const auto describe = [&](const auto& c, double seconds) {
      j.seconds = seconds;
      if (v == Verdict::Passed) return;
      j.message = v == Verdict::Inconclusive ? c.inconclusiveReason()
                                             : fmt::format("{}", fmt::join(c.failures(), ", "));
      j.details = c.report();
    };
    if (stochastic())
      describe(stochasticResults[i], stochasticResults[i].seconds);
    else
      describe(results[i], results[i].test.seconds);
    cases.push_back(std::move(j));
  }
  return stats::junitXml(suite, cases);
}

std::string FamilyResult::json() const {
  nlohmann::json j;
  j["verdict"] = verdictName(verdict());
  j["level"] = level;
  j["per_test_level"] = perTestLevel;
  j["statistical_tests"] = statisticalTests;
  j["parameters"] = nlohmann::json::array();
  for (const FamilyParameter& p : parameters)
    j["parameters"].push_back(
        {{"name", p.name}, {"lo", p.lo}, {"hi", p.hi}, {"logarithmic", p.logarithmic}});
  j["mode"] = stochastic() ? "mean-weight" : "chi-square";
  j["configurations"] = nlohmann::json::array();
  for (size_t i : reportOrder(*this)) {
    const FamilyConfiguration& c = configurations[i];
    nlohmann::json values;
    for (size_t k = 0; k < parameters.size(); ++k) values[parameters[k].name] = c.values[k];
    nlohmann::json e{
        {"name", c.name},
        {"values", values},
        {"corner", c.corner},
        {"incidence_degrees", c.incidence},
        {"below", c.below},
        {"verdict", verdictName(verdictOf(i))},
        {"failed_only_within_rounding", !stochastic() && chi2::failedOnlyByRounding(results[i])}};
    if (stochastic()) {
      const StochasticCheck& t = stochasticResults[i];
      nlohmann::json albedo = nlohmann::json::array();
      for (const WelchComparison& w : t.total)
        albedo.push_back({{"sampled", w.sampled},
                          {"sampled_error", w.sampledError},
                          {"evaluated", w.evaluated},
                          {"evaluated_error", w.evaluatedError},
                          {"p_value", w.p}});
      e.update({{"failures", t.failures()},
                {"inconclusive_reason", t.inconclusiveReason()},
                {"samples", t.samples},
                {"hits", t.hits},
                {"seconds", t.seconds},
                {"worst_per_sample_defect", worstDefect(t.audit)},
                {"albedo", albedo},
                {"cells", t.cells},
                {"cells_rejected", t.rejections},
                {"detectable_albedo_error", t.detectableTotal},
                {"detectable_cell_error", t.detectableCell}});
      j["configurations"].push_back(std::move(e));
      continue;
    }
    const TestResult& t = results[i].test;
    e.update({{"failures", results[i].failures()},
              {"inconclusive_reason", results[i].inconclusiveReason()},
              {"samples", t.samples},
              {"valid_samples", t.valid},
              {"seconds", t.seconds},
              {"worst_per_sample_defect", worstDefect(t.audit)}});
    if (t.chiSquareRan())
      e["chi_square"] = {{"statistic", t.chiSquare.statistic},
                         {"dof", t.chiSquare.dof},
                         {"p_value", t.chiSquare.pValue},
                         {"samples_where_the_density_is_zero", t.chiSquare.outrightSamples}};
    if (t.chiSquarePower.ran())
      e["density_error_quarter"] = t.chiSquarePower.densityError(kStatedMass);
    j["configurations"].push_back(std::move(e));
  }
  return j.dump(1);
}

}  // namespace verity::chi2
