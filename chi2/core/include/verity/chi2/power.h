// What a check could have caught. A PASSED verdict only says that nothing was found; these
// functions turn a test's level, sample count and degrees of freedom into the smallest
// deviation it finds with a stated probability (its power), and back into the sample count
// that a deviation of a given size needs.
//
// The chi-square test: under an alternative whose cell probabilities are p₁ instead of p₀,
// Pearson's statistic is approximately noncentral χ² with the test's dof and noncentrality
// λ = N·w², where w² = Σ (p₁ − p₀)²/p₀ is Cohen's effect size (Cohen 1988, "Statistical Power
// Analysis for the Behavioral Sciences", ch. 7). We state w in words with one family of
// deviations: the density is 1 + ε times the claimed one over cells holding a fraction m of
// the mass and 1 − ε times it over other cells holding m, so that w² = 2·m·ε².
//
// The pdf-integral test: the number of valid samples is binomial, and the Clopper–Pearson
// interval's acceptance region in that count is exact, so its power is computed exactly.
#pragma once

#include <limits>
#include <optional>
#include <string>

namespace verity::chi2 {

// The power a check's statements are made at unless the caller says otherwise.
inline constexpr double kDefaultPower = 0.9;
// The masses the statements are made for: a quarter and a sixteenth of the distribution.
inline constexpr double kStatedMass = 0.25;
inline constexpr double kStatedSmallMass = 1.0 / 16;

// λ such that a noncentral χ²(dof, λ) exceeds the central χ²(dof) quantile 1 − level with
// probability `power`. Throws std::invalid_argument outside dof ≥ 1, 0 < level < 1,
// level < power < 1.
double chiSquareNoncentrality(int dof, double level, double power);

// The relative density error ε over cells holding mass m (compensated over other cells of
// mass m) with effect size w: ε = w / √(2m). Above 1 no such deviation exists.
double densityErrorForEffect(double effectSize, double mass);
double effectForDensityError(double densityError, double mass);

// What a chi-square test of N samples over `dof` degrees of freedom could have caught. As
// default-constructed (dof 0) it is that of a test that did not run (every sample a delta
// lobe, too few cells, an untrustworthy quadrature): it states that it caught nothing.
struct ChiSquarePower {
  int dof = 0;
  double samples = 0;  // the valid samples histogrammed
  double level = 0, power = 0;
  double effectSize = 0;  // Cohen's w found with probability `power`
  bool ran() const { return dof > 0; }
  // +∞ for a test that did not run: no error would have been found.
  double densityError(double mass) const {
    return ran() ? densityErrorForEffect(effectSize, mass)
                 : std::numeric_limits<double>::infinity();
  }
  // "a 1.3% density error over cells holding 1/4 of the mass (5.2% over 1/16), compensated
  // elsewhere, would have been found with 90% probability"; for a test that did not run,
  // "nothing: the chi-square test did not run".
  std::string describe() const;
};
ChiSquarePower chiSquarePower(int dof, double samples, double level, double power);

// What the pdf-integral check of `samples` samples could have caught: the smallest error δ
// of ∫pdf against the sampler's true success probability (either sign that is possible)
// that fails the check with probability `power`. `integral` is the claimed ∫pdf, and
// `tolerance` the quadrature tolerance the check allows.
struct IntegralPower {
  double power = 0;
  std::optional<double> tooHigh;  // ∫pdf = q + δ with q the true success probability
  std::optional<double> tooLow;   // ∫pdf = q − δ
  // The larger of the two, or nothing when neither is possible.
  std::optional<double> detectable() const;
  std::string describe() const;
};
IntegralPower integralPower(double integral, long long samples, double level, double tolerance,
                            double power);

// A question the caller asks of a check: find a density error ε over cells holding mass m
// with probability `power`. The check then chooses its sample count.
struct DetectionTarget {
  double densityError = 0.01;
  double mass = kStatedMass;
  double power = kDefaultPower;
  std::string describe() const;  // "a 1% density error over 1/4 of the mass"
};
// Throws std::invalid_argument naming the field out of range: 0 < ε ≤ 1, 0 < m ≤ 1/2,
// 0 < power < 1.
void validate(const DetectionTarget& target);

}  // namespace verity::chi2
