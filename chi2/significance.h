// Family-wise error control. Every statistical check in the suite (a chi-square test or a
// pdf-integral test) may falsely fail with probability α; over m independent checks the
// Šidák level α = 1 − (1 − α_family)^(1/m) keeps the whole suite's false-failure
// probability at α_family (Šidák 1967, "Rectangular confidence regions for the means of
// multivariate normal distributions", JASA 62).
#pragma once

namespace verity::chi2 {

// The probability that a correct implementation fails the suite anywhere.
inline constexpr double kFamilySignificance = 0.01;

double sidakLevel(double familyLevel, int tests);

// The number of statistical checks the suite declares (counted from its configuration
// lists in suite.cpp) and the per-check level that follows from it.
int declaredTestCount();
double perTestSignificance();

}  // namespace verity::chi2
