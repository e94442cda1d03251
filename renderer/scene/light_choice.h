#pragma once

#include <array>
#include <vector>

#include "lights/light.h"
#include "sampling/distribution.h"

namespace verity {

// The probabilities of choosing each light for next-event estimation at one shading point: by
// each light's contributionEstimate() there (lights that face away get none, near and bright
// ones most), or by power where there is one light or more than kMaxLightsByContribution.
// Made once per shading point, it serves the choice there and the MIS weight of the light that
// the next bounce may hit (Scene::lightChoice).
class LightChoice {
 public:
  // Every choice weighs every light: beyond this many, power is cheaper.
  static constexpr size_t kMaxLightsByContribution = 64;

  // No light to choose.
  LightChoice() = default;
  // By power.
  LightChoice(const std::vector<const Light*>& lights, const Distribution1D& power);
  // By contribution at ref; at most kMaxLightsByContribution lights.
  LightChoice(const std::vector<const Light*>& lights, const Point3f& ref);

  // Null with *pmf 0 where no light can contribute.
  const Light* sample(float u, float* pmf) const;
  float pmf(const Light* light) const;

 private:
  const std::vector<const Light*>* lights_ = nullptr;
  const Distribution1D* power_ = nullptr;  // set when chosen by power
  std::array<double, kMaxLightsByContribution> weight_;
  double total_ = 0;
};

}  // namespace verity
