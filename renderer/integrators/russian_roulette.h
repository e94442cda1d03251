// Russian roulette (Arvo and Kirk 1990, "Particle transport and image synthesis"): a path
// continues past a scattering event with a probability q tied to its throughput, and a
// surviving path's throughput is divided by q, so the estimate keeps its expectation while
// paths that carry little end early. Every integrator that walks paths uses this one rule.
#pragma once

#include "core/math.h"
#include "materials/material.h"

namespace verity {

class Sampler;

// The scattering event at which roulette starts unless the integrator's "rr_depth" says
// otherwise: with 3, the first two bounces are always followed and the roulette first decides
// after the third. README.md records the efficiency study behind this value (`verity bench
// --rr-depth`).
inline constexpr int kDefaultRouletteDepth = 3;

class RussianRoulette {
 public:
  // Roulette decides after scattering event `depth` (1 for the first) and every later one.
  explicit RussianRoulette(int depth = kDefaultRouletteDepth) : depth_(depth) {}

  // Whether a path continues after scattering event `bounce` + 1 (`bounce` counts from 0),
  // given `throughput`, the product of its scattering weights so far (divided by earlier
  // survival probabilities, and excluding what the path started with, such as emitted power,
  // which says nothing about how much a path has lost), and `etaScale`, the product of the
  // η² of the refractions a radiance path has made (refractionEtaScale). The roulette reads
  // throughput · etaScale: radiance inside glass is scaled by 1/η², which is no loss, and
  // reading it would end such paths too often and give the survivors large weights
  // (fireflies). Any function of the path may set the probability, so this stays unbiased;
  // pbrt-v3's path tracer does the same. On survival `*survival` holds the probability to
  // divide the throughput by (exactly 1 before roulette starts). Draws one sample from
  // `sampler` only when roulette decides and the throughput is not zero.
  bool survives(int bounce, const Color3& throughput, float etaScale, Sampler& sampler,
                float* survival) const;

  int depth() const { return depth_; }

 private:
  // The smallest survival probability: a floor keeps the weight 1/q of a surviving path of
  // tiny throughput bounded.
  static constexpr float kMinSurvival = 0.05f;
  int depth_;
};

// What a sampled scattering event multiplies the `etaScale` of survives() by: η² for radiance
// refracted across an interface of relative index η (the material scaled it by 1/η², Veach
// 1997, §5.2), 1 for every other event and for importance, which refraction does not scale.
inline float refractionEtaScale(const BsdfSample& s, TransportMode mode) {
  return mode == TransportMode::Radiance ? s.eta * s.eta : 1.0f;
}

}  // namespace verity
