#include <fmt/format.h>
#include <fmt/ranges.h>
#include <verity/chi2/significance.h>
#include <verity/chi2/stochastic_check.h>
#include <verity/stats/holm.h>
#include <verity/stats/welch_t.h>

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "on_threads.h"

namespace verity::chi2 {

namespace {

using validation::MeanEstimate;

// The mean of n values from their sum and sum of squares.
MeanEstimate meanOf(double sum, double sumSquares, double n) {
  const double mean = sum / n;
  return validation::sampleMean(mean, std::max(0.0, (sumSquares - n * mean * mean) / (n - 1)), n);
}

// The estimate of a sum of independent means: their values, variances and Satterthwaite
// terms add.
void add(MeanEstimate& total, const MeanEstimate& part) {
  total.mean += part.mean;
  total.variance += part.variance;
  total.dfDenominator += part.dfDenominator;
}

// Welch's test of the sampled against the evaluated mean (welch_t.h): t > 0 where the
// sampled one is larger.
WelchComparison welch(const MeanEstimate& sampled, const MeanEstimate& evaluated) {
  const validation::WelchResult w = validation::welchTest(evaluated, sampled);
  return {.sampled = sampled.mean,
          .sampledError = std::sqrt(sampled.variance),
          .evaluated = evaluated.mean,
          .evaluatedError = std::sqrt(evaluated.variance),
          .t = w.t,
          .df = w.df,
          .p = w.p};
}

// The smallest relative error found with 90% power by a two-sided test at `level` whose
// standard error is `error` (normal approximation): (z_{1−level/2} + z_{0.9})·error/|mean|.
double detectable(double level, double error, double mean) {
  const boost::math::normal z;
  const double k =
      boost::math::quantile(boost::math::complement(z, level / 2)) + boost::math::quantile(z, 0.9);
  return mean == 0 ? INFINITY : k * error / std::fabs(mean);
}

}  // namespace

StochasticCheck checkStochasticBsdf(const BsdfModel& model, const Eigen::Vector3d& wiIn,
                                    const StochasticCheckOptions& options) {
  if (options.threads != 0)
    return onThreads(options, [&](const StochasticCheckOptions& o) {
      return checkStochasticBsdf(model, wiIn, o);
    });
  const auto start = std::chrono::steady_clock::now();
  if (!(options.significance > 0 && options.significance < 1))
    throw std::invalid_argument(fmt::format(
        "the per-test significance level must be in (0, 1), not {}", options.significance));
  if (options.samples < 2)
    throw std::invalid_argument(
        fmt::format("the number of samples must be at least 2, not {}", options.samples));
  if (options.strata < 2 || options.strata % 2 != 0)
    throw std::invalid_argument(fmt::format(
        "StochasticCheckOptions::strata must be even and at least 2, not {}", options.strata));
  if (options.resolution < 0)
    throw std::invalid_argument(
        fmt::format("the resolution must be 0 (the default) or more, not {}", options.resolution));
  const Vector3d wi = wiIn.normalized();
  StochasticCheck r;
  r.subject =
      fmt::format("{}, wi ({:.4f}, {:.4f}, {:.4f})",
                  options.name.empty() ? "stochastic bsdf" : options.name, wi.x(), wi.y(), wi.z());
  const uint64_t seed = options.seed ? *options.seed : seedFromName(r.subject);
  const Domain d = sphereDomain(options.resolution > 0 ? options.resolution : 8);
  // Values of any size (RGB, four wavelengths, ...); one whose size only run time tells takes
  // that of eval at wi's mirror direction, as checkBsdf does.
  const int comps =
      model.components > 0
          ? model.components
          : static_cast<int>(model.eval(wi, Vector3d(-wi.x(), -wi.y(), wi.z())).size());
  const int cells = d.cells();
  const auto values = [](const Eigen::ArrayXd& v) {
    return fmt::format("({})", fmt::join(v.data(), v.data() + v.size(), ", "));
  };
  // Whether v has the check's size; records the defect where not, `where()` naming the place.
  const auto sized = [&](const Eigen::ArrayXd& v, const char* what, auto&& where) {
    if (v.size() == comps) return true;
    r.audit.record(Defect::Size, fmt::format("{} {} has {} component(s), the BSDF {}, at {}", what,
                                             values(v), v.size(), comps, where()));
    return false;
  };
  r.significance = options.significance;
  r.samples = options.samples;
  r.cells = cells;
  r.components = comps;

  // Sampling: weight·1[cell] summed per cell and component.
  std::vector<Eigen::ArrayXd> sum(cells, Eigen::ArrayXd::Zero(comps)), sumSquares = sum;
  pcg32 rng(seed, 0);
  std::vector<long long> hits(cells, 0);
  for (long long k = 0; k < options.samples; ++k) {
    BsdfUniforms u;
    u.lobe = uniform01(rng);
    u.xy.x = uniform01(rng);
    u.xy.y = uniform01(rng);
    const std::optional<DirectionSample> s = model.sample(wi, u);
    if (!s) continue;
    if (s->delta) {
      ++r.deltaSamples;
      continue;
    }
    auto at = [&] {
      return fmt::format("wi=({:.7g}) u=({}, {}, {}) wo=({:.7g})",
                         fmt::join(wi.data(), wi.data() + 3, ", "), u.lobe, u.xy.x, u.xy.y,
                         fmt::join(s->wo.data(), s->wo.data() + 3, ", "));
    };
    if (!sized(s->weight, "weight", at)) continue;
    if (!s->wo.allFinite() || !s->weight.allFinite()) {
      r.audit.record(Defect::NonFinite, fmt::format("weight {} at {}", values(s->weight), at()));
      continue;
    }
    if (std::fabs(s->wo.norm() - 1) > 1e-3) {
      r.audit.record(Defect::NotUnit, "sampled direction not a unit vector: " + at());
      continue;
    }
    const int c = d.cellOf(sphereCoords(s->wo));
    ++hits[c];
    sum[c] += s->weight;
    sumSquares[c] += s->weight.square();
  }
  r.hits = std::accumulate(hits.begin(), hits.end(), 0LL);

  // Evaluation: ∫eval·|cos θo| dω over each cell, one jittered direction per stratum on a
  // stream of its own. The variance of a stratified mean is estimated by collapsing strata in
  // pairs, neighbours in φ (Cochran 1977, "Sampling Techniques", §5A.12): Σ (y_a − y_b)² / M²
  // over the M/2 pairs, with M/2 degrees of freedom; it overstates the variance by the
  // squared difference of the paired strata's means only, so the test stays conservative.
  pcg32 jitter(seed, 1);
  const int m = options.strata;
  const double strata = double(m) * m, pairs = strata / 2;
  const double area = d.cellWidth() * d.cellHeight();  // dω = dφ d(cos θ)
  std::vector<std::vector<MeanEstimate>> evaluated(cells, std::vector<MeanEstimate>(comps));
  for (int c = 0; c < cells; ++c) {
    auto at = [&](int i, int j) -> Eigen::ArrayXd {
      const double phi = (c % d.nx + (i + uniform01(jitter)) / m) * d.cellWidth();
      const double z = d.y0 + (c / d.nx + (j + uniform01(jitter)) / m) * d.cellHeight();
      const Vector3d wo = sphereDirection(phi, z);
      const Eigen::ArrayXd y = model.eval(wi, wo) * std::fabs(wo.z());
      const auto where = [&] {
        return fmt::format("wi=({:.7g}) wo=({:.7g})", fmt::join(wi.data(), wi.data() + 3, ", "),
                           fmt::join(wo.data(), wo.data() + 3, ", "));
      };
      if (!sized(y, "eval", where)) return Eigen::ArrayXd::Zero(comps);
      if (y.allFinite()) return y;
      r.audit.record(Defect::NonFinite, fmt::format("eval {} at {}", values(y), where()));
      return Eigen::ArrayXd::Zero(comps);
    };
    Eigen::ArrayXd ySum = Eigen::ArrayXd::Zero(comps), pairSquares = ySum;
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; i += 2) {
        const Eigen::ArrayXd a = at(i, j), b = at(i + 1, j);
        ySum += a + b;
        pairSquares += (a - b).square();
      }
    for (int k = 0; k < comps; ++k) {
      const double v = area * area * pairSquares[k] / (strata * strata);
      evaluated[c][k] = {area * ySum[k] / strata, v, v * v / pairs};
    }
  }
  r.evaluations = static_cast<long long>(cells) * m * m;

  // Each cell with enough hits on its own; the others pooled.
  const double n = static_cast<double>(options.samples);
  std::vector<int> pooled;
  for (int c = 0; c < cells; ++c) {
    if (hits[c] < kStochasticMinHits) {
      pooled.push_back(c);
      continue;
    }
    for (int k = 0; k < comps; ++k) {
      StochasticCellTest t;
      static_cast<WelchComparison&>(t) =
          welch(meanOf(sum[c][k], sumSquares[c][k], n), evaluated[c][k]);
      t.cell = c, t.component = k, t.hits = hits[c];
      r.cellTests.push_back(t);
    }
  }
  r.pooledCells = static_cast<int>(pooled.size());
  long long poolHits = 0;
  for (int c : pooled) poolHits += hits[c];
  for (int k = 0; k < comps; ++k) {
    double s = 0, s2 = 0, ts = 0, ts2 = 0;
    MeanEstimate pool, all;
    for (int c = 0; c < cells; ++c) {
      ts += sum[c][k], ts2 += sumSquares[c][k];
      add(all, evaluated[c][k]);
    }
    for (int c : pooled) {
      s += sum[c][k], s2 += sumSquares[c][k];
      add(pool, evaluated[c][k]);
    }
    if (!pooled.empty() && poolHits >= kStochasticMinHits) {
      StochasticCellTest t;
      static_cast<WelchComparison&>(t) = welch(meanOf(s, s2, n), pool);
      t.component = k, t.hits = poolHits;
      r.cellTests.push_back(t);
    }
    r.total.push_back(welch(meanOf(ts, ts2, n), all));
  }

  // The total albedo: its components at the Šidák level for their number.
  const double componentLevel = sidakLevel(options.significance, comps);
  for (const WelchComparison& w : r.total) {
    r.totalPassed = r.totalPassed && w.p > componentLevel;
    r.detectableTotal = std::max(
        r.detectableTotal,
        detectable(componentLevel, std::hypot(w.sampledError, w.evaluatedError), w.evaluated));
  }

  // The cells by Holm's step-down procedure (holm.h).
  std::vector<double> p;
  for (const StochasticCellTest& t : r.cellTests) p.push_back(t.p);
  const validation::HolmResult holm = validation::holmBonferroni(p, options.significance);
  for (std::size_t i = 0; i < p.size(); ++i) r.cellTests[i].rejected = holm.rejected[i];
  r.rejections = holm.rejections;
  const double tests = static_cast<double>(p.size());
  r.detectableCell = INFINITY;
  for (const StochasticCellTest& t : r.cellTests)
    r.detectableCell = std::min(
        r.detectableCell, detectable(options.significance / tests,
                                     std::hypot(t.sampledError, t.evaluatedError), t.evaluated));
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::string StochasticCheck::inconclusiveReason() const {
  if (!audit.clean()) return {};
  if (hits < kStochasticMinHits)
    return fmt::format(
        "only {} of {} draws returned a non-delta direction: the normal approximation needs {}",
        hits, samples, kStochasticMinHits);
  bool scatters = false;
  for (const WelchComparison& w : total) scatters = scatters || w.sampled != 0 || w.evaluated != 0;
  if (!scatters) return "the weights and eval are zero everywhere: nothing scatters from wi";
  return {};
}

Verdict StochasticCheck::verdict() const {
  if (!audit.clean()) return Verdict::Failed;
  if (!inconclusiveReason().empty()) return Verdict::Inconclusive;
  if (!totalPassed || rejections > 0) return Verdict::Failed;
  return Verdict::Passed;
}

std::vector<std::string> StochasticCheck::failures() const {
  std::vector<std::string> out;
  if (verdict() == Verdict::Inconclusive) {
    out.push_back("inconclusive");
  } else {
    if (!totalPassed) out.push_back("total albedo");
    if (rejections > 0) out.push_back("cells");
  }
  for (int d = 0; d < static_cast<int>(Defect::Count); ++d)
    if (audit.count(static_cast<Defect>(d)) > 0) out.push_back(defectName(static_cast<Defect>(d)));
  return out;
}

bool StochasticCheck::failed(const std::string& check) const {
  const std::vector<std::string> f = failures();
  return std::find(f.begin(), f.end(), check) != f.end();
}

std::string StochasticCheck::report() const {
  std::string s = fmt::format(
      "{}\n  stochastic check: {} draws ({} in a direction, {} delta), {} evaluations on {} "
      "cells, significance {:.3g} (Sidak)\n",
      subject, samples, hits, deltaSamples, evaluations, cells, significance);
  for (std::size_t k = 0; k < total.size(); ++k) {
    const WelchComparison& w = total[k];
    s += fmt::format(
        "  [{}] total albedo{}: sampled {:.6g} +- {:.2g}, evaluated {:.6g} +- {:.2g}, Welch t "
        "{:.3f}, df {:.0f}, p {:.3g}\n",
        totalPassed ? "pass" : "FAIL", total.size() > 1 ? fmt::format(" [{}]", k) : "", w.sampled,
        w.sampledError, w.evaluated, w.evaluatedError, w.t, w.df, w.p);
  }
  const StochasticCellTest* worst = nullptr;
  for (const StochasticCellTest& t : cellTests)
    if (!worst || t.p < worst->p) worst = &t;
  s += fmt::format("  [{}] cells: {} Welch tests ({} cells pooled), Holm rejects {}",
                   rejections == 0 ? "pass" : "FAIL", cellTests.size(), pooledCells, rejections);
  if (worst)
    s +=
        fmt::format("; smallest p {:.3g} in {} [{}]: sampled {:.6g} vs evaluated {:.6g}", worst->p,
                    worst->cell < 0 ? std::string("the pool") : fmt::format("cell {}", worst->cell),
                    worst->component, worst->sampled, worst->evaluated);
  s += fmt::format(
      "\n  could have caught, with 90% power (normal approximation): a relative error of {:.2g} "
      "in the total albedo, {:.2g} in the best cell's mean\n",
      detectableTotal, detectableCell);
  s += fmt::format("  [{}] {}\n", audit.clean() ? "pass" : "FAIL", audit.describe());
  const std::string reason = inconclusiveReason();
  if (!reason.empty()) s += fmt::format("  inconclusive: {}\n", reason);
  s += fmt::format("  {} in {:.2f} s", verdictName(verdict()), seconds);
  return s;
}

}  // namespace verity::chi2
