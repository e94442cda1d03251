#include <verity/stats/holm.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace verity::validation {

HolmResult holmBonferroni(const std::vector<double>& pValues, double alpha) {
  if (!(alpha > 0 && alpha < 1)) throw std::invalid_argument("holmBonferroni: alpha not in (0, 1)");
  for (double p : pValues)
    if (!(p >= 0 && p <= 1)) throw std::invalid_argument("holmBonferroni: p-value not in [0, 1]");
  const size_t m = pValues.size();
  HolmResult r;
  r.alpha = alpha;
  r.adjusted.assign(m, 1.0);
  r.rejected.assign(m, false);
  std::vector<size_t> order(m);
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t i, size_t j) { return pValues[i] < pValues[j]; });
  // Step down: rejections continue while p_(k) ≤ α / (m − k + 1) (k from 1).
  bool stopped = false;
  double running = 0;
  for (size_t k = 0; k < m; ++k) {
    const double p = pValues[order[k]];
    const double remaining = double(m - k);  // m − k + 1 with k counted from 1
    running = std::max(running, std::min(1.0, remaining * p));
    r.adjusted[order[k]] = running;
    if (!stopped && p <= alpha / remaining) {
      r.rejected[order[k]] = true;
      ++r.rejections;
    } else {
      stopped = true;
    }
  }
  return r;
}

}  // namespace verity::validation
