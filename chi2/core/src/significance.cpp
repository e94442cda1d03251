#include <verity/chi2/significance.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace verity::chi2 {

double sidakLevel(double familyLevel, int tests) {
  if (!(familyLevel > 0 && familyLevel < 1))
    throw std::invalid_argument("family-wise significance level " + std::to_string(familyLevel) +
                                " is not in (0, 1)");
  if (tests < 1)
    throw std::invalid_argument("the number of tests must be at least 1, not " +
                                std::to_string(tests));
  // 1 − (1 − a)^(1/m) computed without cancellation for small a.
  return -std::expm1(std::log1p(-familyLevel) / tests);
}

}  // namespace verity::chi2
