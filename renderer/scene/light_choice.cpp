#include "scene/light_choice.h"

namespace verity {

LightChoice::LightChoice(const std::vector<const Light*>& lights, const Distribution1D& power)
    : lights_(&lights), power_(&power) {}

LightChoice::LightChoice(const std::vector<const Light*>& lights, const Point3f& ref)
    : lights_(&lights) {
  for (size_t i = 0; i < lights.size(); ++i)
    total_ += weight_[i] = lights[i]->contributionEstimate(ref);
}

const Light* LightChoice::sample(float u, float* pmf) const {
  *pmf = 0;
  if (!lights_ || lights_->empty()) return nullptr;
  if (power_) return (*lights_)[power_->sampleDiscrete(u, pmf)];
  if (!(total_ > 0)) return nullptr;
  const double target = double{u} * total_;
  double below = 0;
  size_t chosen = 0;
  // The last light of positive weight catches a target that rounding put past the sum.
  for (size_t i = 0; i < lights_->size(); ++i) {
    if (!(weight_[i] > 0)) continue;
    chosen = i;
    if (target < below + weight_[i]) break;
    below += weight_[i];
  }
  *pmf = static_cast<float>(weight_[chosen] / total_);
  return (*lights_)[chosen];
}

float LightChoice::pmf(const Light* light) const {
  if (!light || !lights_) return 0;
  if (power_) return power_->pmf(light->index);
  return total_ > 0 ? static_cast<float>(weight_[light->index] / total_) : 0;
}

}  // namespace verity
