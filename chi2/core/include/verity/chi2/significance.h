// Family-wise error control for a caller that runs several statistical checks. Each check
// (a chi-square test, a pdf-integral test) may falsely fail with probability α; over m
// independent checks the Šidák level α = 1 − (1 − α_family)^(1/m) keeps the probability
// that a correct implementation fails anywhere at α_family (Šidák 1967, "Rectangular
// confidence regions for the means of multivariate normal distributions", JASA 62).
#pragma once

namespace verity::chi2 {

// The per-check level for `tests` checks at family-wise level `familyLevel`. Throws
// std::invalid_argument unless 0 < familyLevel < 1 and tests ≥ 1.
double sidakLevel(double familyLevel, int tests);

}  // namespace verity::chi2
