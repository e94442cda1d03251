#include "density.h"

#include <algorithm>

namespace verity::chi2 {

void Density::wait(const Point2d* points, double* values, size_t n,
                   std::coroutine_handle<> computation) {
  points_.insert(points_.end(), points, points + n);
  waiting_.push_back({values, n, computation});
}

void Density::evaluate() {
  values_.resize(points_.size());
  if (points_.size() <= kMostPerCall) {
    (*batch_)(points_, values_);
  } else {
    std::vector<Point2d> part;
    std::vector<double> partValues;
    for (size_t from = 0; from < points_.size(); from += kMostPerCall) {
      const size_t to = std::min(points_.size(), from + kMostPerCall);
      part.assign(points_.begin() + static_cast<std::ptrdiff_t>(from),
                  points_.begin() + static_cast<std::ptrdiff_t>(to));
      partValues.resize(part.size());
      (*batch_)(part, partValues);
      std::copy(partValues.begin(), partValues.end(),
                values_.begin() + static_cast<std::ptrdiff_t>(from));
    }
  }
  // The computations take their values in the order they asked, and resume in that order.
  size_t next = 0;
  for (const Waiting& w : waiting_) {
    std::copy_n(values_.begin() + static_cast<std::ptrdiff_t>(next), w.n, w.values);
    next += w.n;
  }
  for (auto w = waiting_.rbegin(); w != waiting_.rend(); ++w) ready_.push_back(w->computation);
  points_.clear();
  waiting_.clear();
}

}  // namespace verity::chi2
