// The Holm–Bonferroni step-down procedure (S. Holm 1979, "A simple sequentially rejective
// multiple test procedure", Scandinavian Journal of Statistics 6(2), 65–70).
//
// Order the m p-values p_(1) ≤ … ≤ p_(m). Reject H_(1), …, H_(k−1), where k is the smallest
// index with p_(k) > α / (m − k + 1) (reject all when there is none). The probability of
// rejecting any true hypothesis is at most α whatever the dependence between the tests.
// Equivalently, the adjusted p-value p̃_(i) = max_{j ≤ i} min(1, (m − j + 1) p_(j)) is
// rejected when p̃ ≤ α. At least one hypothesis is rejected exactly when min p ≤ α / m.
#pragma once

#include <vector>

namespace verity::validation {

struct HolmResult {
  double alpha = 0;              // the family-wise level
  std::vector<double> adjusted;  // adjusted p-values, in the input order
  std::vector<bool> rejected;    // in the input order
  int rejections = 0;
};

// p-values must lie in [0, 1] (std::invalid_argument otherwise); alpha in (0, 1).
HolmResult holmBonferroni(const std::vector<double>& pValues, double alpha);

}  // namespace verity::validation
