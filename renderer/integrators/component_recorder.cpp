#include "integrators/component_recorder.h"

#include "integrators/integrator.h"

namespace verity {

void ComponentRecorder::addStrategy(int s, int t, const Color3& weighted,
                                    const Color3& unweighted) {
  if (layout_->kind() == ComponentLayout::Kind::PathLengths) {
    addPathLength(s + t - 2, weighted);
    return;
  }
  add(layout_->strategyIndex(s, t, true), weighted);
  add(layout_->strategyIndex(s, t, false), unweighted);
}

void ComponentRecorder::splatStrategy(int s, const Point2f& film, const Color3& weighted,
                                      const Color3& unweighted) {
  const auto pixel = filmPixel(film, resolution_);
  if (!pixel || !weighted.allFinite()) return;
  const size_t i = size_t(pixel->y()) * resolution_.x() + pixel->x();
  if (layout_->kind() == ComponentLayout::Kind::PathLengths) {
    splat(layout_->pathLengthIndex(s - 1), i, weighted);
    return;
  }
  splat(layout_->strategyIndex(s, 1, true), i, weighted);
  splat(layout_->strategyIndex(s, 1, false), i, unweighted);
}

}  // namespace verity
