#include "chi2/significance.h"

#include <cmath>

#include "chi2/suite.h"

namespace verity::chi2 {

double sidakLevel(double familyLevel, int tests) {
  // 1 − (1 − a)^(1/m) computed without cancellation for small a.
  return -std::expm1(std::log1p(-familyLevel) / tests);
}

int declaredTestCount() {
  static const int count = suite::statisticalCheckCount();
  return count;
}

double perTestSignificance() {
  return sidakLevel(kFamilySignificance, declaredTestCount());
}

}  // namespace verity::chi2
