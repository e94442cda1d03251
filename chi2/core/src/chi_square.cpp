#include <fmt/format.h>
#include <verity/chi2/chi_square.h>

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <limits>

namespace verity::chi2 {

double outrightThreshold(double significance, int cells) {
  return 1e-3 * significance / cells;
}

namespace {

// Cells expecting fewer than 5 samples are pooled; the pool is a cell of its own when it
// expects 5 or more (or nothing else is left), else it joins the smallest regular cell.
// Returns (expected, observed) per tested cell; `observed` may be empty (planning).
std::vector<std::pair<double, double>> poolCells(const std::vector<double>& expected,
                                                 const std::vector<long long>& observed,
                                                 int& pooledCells, double& pooledExpected) {
  double poolE = 0, poolO = 0;
  pooledCells = 0;
  std::vector<std::pair<double, double>> regular;
  for (size_t c = 0; c < expected.size(); ++c) {
    const double o = observed.empty() ? 0.0 : static_cast<double>(observed[c]);
    if (expected[c] < 5) {
      poolE += expected[c];
      poolO += o;
      ++pooledCells;
    } else {
      regular.emplace_back(expected[c], o);
    }
  }
  pooledExpected = poolE;
  if (poolE > 0 || poolO > 0) {
    if (poolE >= 5 || regular.empty()) {
      regular.emplace_back(poolE, poolO);
    } else {
      auto smallest = std::min_element(regular.begin(), regular.end());
      smallest->first += poolE;
      smallest->second += poolO;
    }
  }
  return regular;
}

}  // namespace

int plannedDof(const std::vector<double>& expected) {
  int pooled = 0;
  double pooledExpected = 0;
  const size_t cells = poolCells(expected, {}, pooled, pooledExpected).size();
  return cells < 2 ? 0 : static_cast<int>(cells) - 1;
}

ChiSquareResult chiSquareTest(const std::vector<double>& expected,
                              const std::vector<long long>& observed, double threshold) {
  ChiSquareResult r;
  r.outrightThreshold = threshold;
  for (size_t c = 0; c < expected.size(); ++c) {
    if (expected[c] < threshold && observed[c] > 0) {
      r.outrightSamples += observed[c];
      if (r.outrightCell < 0) {
        r.outrightCell = static_cast<int>(c);
        r.outrightExpected = expected[c];
      }
    }
  }
  const std::vector<std::pair<double, double>> regular =
      poolCells(expected, observed, r.pooledCells, r.pooledExpected);
  r.regularCells = static_cast<int>(regular.size());
  if (regular.size() < 2) {
    r.degenerate = true;
    return r;
  }
  for (const auto& [e, o] : regular) {
    if (e <= 0) {  // a pool with no expectation but samples in it
      r.statistic = std::numeric_limits<double>::infinity();
      break;
    }
    r.statistic += (o - e) * (o - e) / e;
  }
  r.dof = static_cast<int>(regular.size()) - 1;
  if (!std::isfinite(r.statistic)) {
    r.pValue = 0;
  } else {
    boost::math::chi_squared_distribution<double> dist(r.dof);
    r.pValue = boost::math::cdf(boost::math::complement(dist, r.statistic));
  }
  return r;
}

std::string ChiSquareResult::describe() const {
  std::string s;
  if (degenerate) {
    s = fmt::format("chi-square: degenerate ({} cell(s) after pooling), no test", regularCells);
  } else {
    s = fmt::format(
        "chi-square: statistic {:.4g}, dof {}, p-value {:.4g} ({} cells, {} pooled "
        "with expected {:.3g})",
        statistic, dof, pValue, regularCells, pooledCells, pooledExpected);
  }
  if (outrightSamples > 0)
    s += fmt::format("; {} sample(s) where the density is zero (cell {} expects {:.3g} < {:.3g})",
                     outrightSamples, outrightCell, outrightExpected, outrightThreshold);
  return s;
}

}  // namespace verity::chi2
