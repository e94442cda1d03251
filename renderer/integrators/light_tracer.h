// Light tracing (particle tracing with connections to the camera; Arvo and Kirk 1990,
// "Particle Transport and Image Synthesis"; Veach 1997, §10.2 strategy t = 1): each camera
// sample traces one light subpath and connects each of its vertices to a point on the lens,
// splatting the contribution to the pixel it lands on. The renderer traces one light path
// per pixel per pass, so each splat is the whole estimate of its light path for that pass,
// with the camera's importance normalised over the image plane.
//
// It estimates exactly the light whose first surface seen from the camera is not a pure
// delta surface, and the emitting background where the camera sees it directly: a light
// subpath that starts on the environment (from a disk bounding the scene, pbrt-v3 §16.1.5)
// is also connected to the lens along its own direction. It cannot see anything seen only in
// a mirror or through smooth glass.
// Bounces are counted as in every integrator: a light path of s vertices connected to the
// camera has s − 1 bounces, at most max_bounces.
#pragma once

#include "integrators/integrator.h"
#include "integrators/russian_roulette.h"

namespace verity {

class LightTracer : public Integrator {
 public:
  LightTracer(int maxBounces, RussianRoulette roulette)
      : maxBounces_(maxBounces), roulette_(roulette) {}
  // Always black: everything this integrator estimates arrives through splats.
  Color3 Li(const Scene& scene, Sampler& sampler, const Ray& ray,
            SampleContext& context) const override;

 private:
  int maxBounces_;
  RussianRoulette roulette_;
};

}  // namespace verity
