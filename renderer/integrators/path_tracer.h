// Unidirectional path tracing with one of three ways to find emitters:
//   Materials:  emission is found only by sampling the material (path_tracer_mats);
//   NextEvent:  a light is sampled at every non-delta vertex, and emission hit by a
//               material sample counts only after delta bounces (path_tracer_nee);
//   Mis:        both, weighted by the balance or power heuristic (Veach and Guibas 1995,
//               "Optimally Combining Sampling Techniques for Monte Carlo Rendering").
#pragma once

#include "integrators/integrator.h"
#include "integrators/russian_roulette.h"

namespace verity {

class PathTracer : public Integrator {
 public:
  enum class Strategy { Materials, NextEvent, Mis };

  PathTracer(Strategy strategy, int maxBounces, float misPower, RussianRoulette roulette)
      : strategy_(strategy), maxBounces_(maxBounces), misPower_(misPower), roulette_(roulette) {}
  Color3 Li(const Scene& scene, Sampler& sampler, const Ray& ray,
            SampleContext& context) const override;

 private:
  // Weight of a strategy of density `pdf` against one of density `other`.
  float misWeight(float pdf, float other) const;
  // Weight of emission found by material sampling with density `bsdfPdf` when light
  // sampling had density `lightPdf` for the same point.
  float emissionWeight(bool countedByLightSampling, float bsdfPdf, float lightPdf) const;
  // Next-event estimation at si with a light drawn from `choice`, made at si.p.
  Color3 sampleLight(const Scene& scene, const LightChoice& choice, Sampler& sampler,
                     const SurfaceInteraction& si, const Vector3f& wi,
                     SampleContext& context) const;

  Strategy strategy_;
  int maxBounces_;
  float misPower_;
  RussianRoulette roulette_;
};

}  // namespace verity
