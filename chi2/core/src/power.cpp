#include <fmt/format.h>
#include <verity/chi2/power.h>

#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/non_central_chi_squared.hpp>
#include <cmath>
#include <stdexcept>

namespace verity::chi2 {

namespace {

void requireOpenUnit(double value, const char* what) {
  if (!(value > 0 && value < 1))
    throw std::invalid_argument(fmt::format("{} must be in (0, 1), not {}", what, value));
}

// "1/4" for a mass that is the reciprocal of a whole number, else "3.5%".
std::string massText(double mass) {
  const double k = 1 / mass;
  if (std::abs(k - std::round(k)) < 1e-9 * k) return fmt::format("1/{:.0f}", std::round(k));
  return fmt::format("{:.3g}%", 100 * mass);
}

std::string percent(double fraction) {
  return fmt::format("{:.2g}%", 100 * fraction);
}

}  // namespace

double chiSquareNoncentrality(int dof, double level, double power) {
  if (dof < 1) throw std::invalid_argument(fmt::format("dof must be at least 1, not {}", dof));
  requireOpenUnit(level, "the level");
  requireOpenUnit(power, "the power");
  if (power <= level)
    throw std::invalid_argument(fmt::format(
        "the power {} must exceed the level {}: a test finds nothing below it", power, level));
  const double critical =
      boost::math::quantile(boost::math::complement(boost::math::chi_squared(dof), level));
  // λ with P(χ'²(dof, λ) ≤ critical) = 1 − power.
  return boost::math::non_central_chi_squared::find_non_centrality(dof, critical, 1 - power);
}

double densityErrorForEffect(double effectSize, double mass) {
  return effectSize / std::sqrt(2 * mass);
}

double effectForDensityError(double densityError, double mass) {
  return densityError * std::sqrt(2 * mass);
}

ChiSquarePower chiSquarePower(int dof, double samples, double level, double power) {
  ChiSquarePower p;
  p.dof = dof;
  p.samples = samples;
  p.level = level;
  p.power = power;
  p.effectSize = std::sqrt(chiSquareNoncentrality(dof, level, power) / samples);
  return p;
}

std::string ChiSquarePower::describe() const {
  if (!ran()) return "nothing: the chi-square test did not run";
  const double quarter = densityError(kStatedMass), sixteenth = densityError(kStatedSmallMass);
  if (quarter > 1)
    return fmt::format(
        "no density error over cells holding {} of the mass would be found with {} probability "
        "(effect size w = {:.3g}, Cohen 1988)",
        massText(kStatedMass), percent(power), effectSize);
  const std::string small =
      sixteenth > 1 ? fmt::format("none over {}", massText(kStatedSmallMass))
                    : fmt::format("{} over {}", percent(sixteenth), massText(kStatedSmallMass));
  return fmt::format(
      "a {} density error over cells holding {} of the mass ({}), compensated elsewhere, would "
      "have been found with {} probability (effect size w = {:.3g}, Cohen 1988)",
      percent(quarter), massText(kStatedMass), small, percent(power), effectSize);
}

std::optional<double> IntegralPower::detectable() const {
  if (tooHigh && tooLow) return std::max(*tooHigh, *tooLow);
  return tooHigh ? tooHigh : tooLow;
}

std::string IntegralPower::describe() const {
  const std::optional<double> d = detectable();
  if (!d) return "no normalisation error could have been found";
  return fmt::format("a normalisation error of {:.2g} would have been found with {} probability",
                     *d, percent(power));
}

IntegralPower integralPower(double integral, long long samples, double level, double tolerance,
                            double power) {
  using boost::math::binomial_distribution;
  IntegralPower r;
  r.power = power;
  if (!std::isfinite(integral) || samples < 1) return r;
  const double n = static_cast<double>(samples), half = level / 2;
  // The check (integral_check.cpp) passes a count k iff upper(k) ≥ I − tol and
  // lower(k) ≤ I + tol; both bounds grow with k, so it fails exactly below kLow or above kHigh.
  const auto upper = [&](long long k) {
    return k == samples ? 1.0 : binomial_distribution<double>::find_upper_bound_on_p(n, k, half);
  };
  const auto lower = [&](long long k) {
    return k == 0 ? 0.0 : binomial_distribution<double>::find_lower_bound_on_p(n, k, half);
  };
  const auto firstCount = [&](auto&& holds) {  // the smallest k in [0, N + 1) where holds(k)
    long long lo = 0, hi = samples + 1;
    while (lo < hi) {
      const long long mid = lo + (hi - lo) / 2;
      holds(mid) ? hi = mid : lo = mid + 1;
    }
    return lo;
  };
  const long long kLow = firstCount([&](long long k) { return upper(k) >= integral - tolerance; });
  const long long kHigh =
      firstCount([&](long long k) { return lower(k) > integral + tolerance; }) - 1;
  // The smallest distance from I at which a true success probability q fails the check with
  // probability `power`, found by bisection on q (the failure probability is monotone in q).
  const auto bisect = [&](double from, double to, auto&& failure) -> std::optional<double> {
    if (failure(to) < power) return std::nullopt;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (from + to);
      (failure(mid) >= power ? to : from) = mid;
    }
    return std::abs(to - integral);
  };
  if (kLow > 0 && integral - tolerance > 0)
    r.tooHigh = bisect(std::min(1.0, integral - tolerance), 0.0, [&](double q) {
      return boost::math::cdf(binomial_distribution<double>(n, q), kLow - 1.0);
    });
  if (kHigh < samples && integral + tolerance < 1)
    r.tooLow = bisect(std::max(0.0, integral + tolerance), 1.0, [&](double q) {
      return boost::math::cdf(
          boost::math::complement(binomial_distribution<double>(n, q), static_cast<double>(kHigh)));
    });
  return r;
}

std::string DetectionTarget::describe() const {
  return fmt::format("a {} density error over cells holding {} of the mass with {} probability",
                     percent(densityError), massText(mass), percent(power));
}

void validate(const DetectionTarget& target) {
  if (!(target.densityError > 0 && target.densityError <= 1))
    throw std::invalid_argument(
        fmt::format("the density error to detect must be in (0, 1], not {}", target.densityError));
  if (!(target.mass > 0 && target.mass <= 0.5))
    throw std::invalid_argument(
        fmt::format("the mass the density error covers must be in (0, 1/2], not {}", target.mass));
  requireOpenUnit(target.power, "the power");
}

}  // namespace verity::chi2
