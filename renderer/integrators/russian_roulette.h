// Russian roulette (Arvo and Kirk 1990, "Particle transport and image synthesis"): a path
// continues past a scattering event with a probability q tied to its throughput, and a
// surviving path's throughput is divided by q, so the estimate keeps its expectation while
// paths that carry little end early. Every integrator that walks paths uses this one rule.
#pragma once

#include "core/math.h"
#include "materials/material.h"

namespace verity {

class Sampler;

// The non-specular scattering event at which roulette starts unless the integrator's
// "rr_depth" says otherwise: with 3, a path is always followed through its first two
// non-specular events, and the roulette first decides after the third.
// reports/validation-findings.md records the efficiency studies behind this value and behind not
// counting specular events (`verity bench
// --rr-depth`).
inline constexpr int kDefaultRouletteDepth = 3;
// The throughput below which roulette may end a path unless the integrator's "rr_threshold"
// says otherwise: a path of throughput t survives with probability t / threshold. The best
// value depends on what it costs to go on: a path tracer's next vertex costs two rays, BDPT's
// a connection to every vertex of the other subpath. reports/validation-findings.md records
// the study behind each value (`verity bench --rr-threshold`).
inline constexpr float kPathTracerRouletteThreshold = 0.5f;
inline constexpr float kBdptRouletteThreshold = 1;
inline constexpr float kLightTracerRouletteThreshold = 1;

// What the roulette reads of a path besides its throughput, brought up to date after each
// sampled scattering event by record().
struct RouletteHistory {
  // Scattering events that sampled a non-delta lobe. Specular events (a mirror, smooth glass)
  // do not count towards the roulette's start: a sampled specular event loses little or
  // nothing, and counting it made the roulette end paths through glass and mirrors at their
  // first diffuse bounces after them, where the paths that light a caustic have barely begun.
  int nonDeltaEvents = 0;
  // The product of the η² of the refractions a radiance path has made (1 for importance, which
  // refraction does not scale; Veach 1997, §5.2). Radiance inside glass is scaled by 1/η²,
  // which is no loss: the roulette reads throughput · etaScale, else it would end such paths
  // too often and give the survivors large weights (fireflies).
  float etaScale = 1;

  void record(const BsdfSample& event, TransportMode mode) {
    if (!event.isDelta()) ++nonDeltaEvents;
    if (mode == TransportMode::Radiance) etaScale *= event.eta * event.eta;
  }
};

class RussianRoulette {
 public:
  // Roulette decides once the path has made `depth` non-specular scattering events (1: from
  // the first on), after every later event, specular ones included.
  RussianRoulette(int depth, float threshold) : depth_(depth), threshold_(threshold) {}

  // Whether a path with `history` continues after its latest scattering event, given
  // `throughput`, the product of its scattering weights so far (divided by earlier survival
  // probabilities, and excluding what the path started with, such as emitted power, which says
  // nothing about how much a path has lost). The survival probability is
  // throughput · etaScale / threshold, clamped to [kMinSurvival, 1]; any function of the path
  // may set it, so this stays unbiased; pbrt-v3's path tracer reads the same product, and its
  // "rrthreshold" the same threshold below which roulette may end a path (there it does not
  // scale the probability). On survival `*survival` holds the
  // probability to divide the throughput by (exactly 1 before roulette starts). Draws one
  // sample from `sampler` only when roulette decides and the throughput is not zero.
  bool survives(const RouletteHistory& history, const Color3& throughput, Sampler& sampler,
                float* survival) const;

  int depth() const { return depth_; }
  float threshold() const { return threshold_; }

 private:
  // The smallest survival probability: a floor keeps the weight 1/q of a surviving path of
  // tiny throughput bounded.
  static constexpr float kMinSurvival = 0.05f;
  int depth_;
  float threshold_;
};

}  // namespace verity
