// Spending a significance level over the looks of a sequential test (K. K. G. Lan and
// D. L. DeMets 1983, "Discrete sequential boundaries for clinical trials", Biometrika 70(3),
// 659–663). A spending function α*(t) rises from α*(0) = 0 to α*(1) = α over the fraction t of
// the planned looks; look k of K is tested at the level spent since the previous look,
//     α_k = α*(k/K) − α*((k − 1)/K),
// so that Σ_k α_k = α. By the union bound (Bonferroni over the looks), the probability that any
// look rejects a true hypothesis is at most Σ_k α_k = α, whatever the dependence between the
// looks: the t-tests of growing samples need no joint distribution, at the price of boundaries
// more conservative than Lan and DeMets' exact ones. Stopping before look K spends less than α.
//
// Two spending functions of Lan and DeMets (1983):
// - Pocock-type, α ln(1 + (e − 1) t): most of the level early, for early decisions;
// - O'Brien–Fleming-type, 2 − 2 Φ(z_{1−α/2} / √t): almost nothing early, nearly α at the end.
#pragma once

#include <string>

namespace verity::validation {

enum class SpendingFunction { Pocock, OBrienFleming };

// "pocock" or "obrien-fleming"; std::invalid_argument otherwise.
SpendingFunction spendingFunction(const std::string& name);
std::string spendingName(SpendingFunction f);

// α*(t) for t in [0, 1] and α in (0, 1); std::invalid_argument outside.
double spentLevel(SpendingFunction f, double alpha, double t);

// α_k of look `look` (1 ≤ look ≤ looks); std::invalid_argument outside.
double lookLevel(SpendingFunction f, double alpha, int look, int looks);

}  // namespace verity::validation
