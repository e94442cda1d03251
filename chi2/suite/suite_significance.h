// The sampling suite's own significance: the suite is one caller of the core's Šidák
// correction, over the statistical checks it declares.
#pragma once

#include <verity/chi2/significance.h>

namespace verity::chi2 {

// The probability that a correct implementation fails the suite anywhere.
inline constexpr double kFamilySignificance = 0.01;

// The number of statistical checks the suite declares (counted from its configuration
// lists in suite.cpp) and the per-check level that follows from it.
int declaredTestCount();
double perTestSignificance();

}  // namespace verity::chi2
