// Bidirectional path tracing (Veach and Guibas 1994, "Bidirectional Estimators for Light
// Transport"; Veach 1997, ch. 10). Each camera sample traces a camera subpath and a light
// subpath and evaluates every strategy (s, t) with s ≥ 0 light and t ≥ 1 camera vertices and
// at most max_bounces scattering events (s + t − 2 ≤ max_bounces):
//   s = 0   the camera subpath hits an emitter or escapes to an emitting background;
//   s = 1   next-event estimation with the scene's light sampling;
//   t = 1   the light subpath is connected to the lens and splatted to the pixel it lands
//           on (one light path per camera sample, so the splat is that path's whole
//           estimate; the camera's importance is normalised over the image plane);
//   others  an edge between a camera and a light vertex.
// The strategy t = 0 (a light subpath reaching the lens) is not used: a pinhole is a point
// no ray can hit, and the thin lens is not part of the scene's geometry either, so for both
// cameras it would need a separate intersection with the lens disk. The MIS weights leave it
// out, so the remaining strategies still sum to one. Strategies that would connect at a delta
// vertex (mirror, smooth glass) are skipped and left out of the weights.
//
// Scratch space: the subpaths live in per-thread vectors that keep their capacity, so after
// the first samples a sample allocates nothing.
#pragma once

#include "integrators/integrator.h"
#include "integrators/russian_roulette.h"

namespace verity {

// A strategy: s light subpath vertices and t camera subpath vertices.
struct BdptStrategy {
  int s = -1, t = -1;
};

class Bdpt : public Integrator {
 public:
  // `dropped`, a test hook, names a strategy whose contribution is left out (the default names
  // none): the tests that compare BDPT with path tracing must then fail.
  Bdpt(int maxBounces, float misPower, RussianRoulette roulette, BdptStrategy dropped = {})
      : maxBounces_(maxBounces), misPower_(misPower), roulette_(roulette), dropped_(dropped) {}
  Color3 Li(const Scene& scene, Sampler& sampler, const Ray& ray,
            SampleContext& context) const override;

 private:
  bool isDropped(int s, int t) const { return s == dropped_.s && t == dropped_.t; }

  int maxBounces_;
  float misPower_;
  RussianRoulette roulette_;
  BdptStrategy dropped_;
};

}  // namespace verity
