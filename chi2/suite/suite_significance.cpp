#include "chi2/suite/suite_significance.h"

#include "chi2/suite/suite.h"

namespace verity::chi2 {

int declaredTestCount() {
  static const int count = suite::statisticalCheckCount();
  return count;
}

double perTestSignificance() {
  return sidakLevel(kFamilySignificance, declaredTestCount());
}

}  // namespace verity::chi2
