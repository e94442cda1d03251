#include "integrators/path_tracer.h"

namespace verity {

float PathTracer::misWeight(float pdf, float other) const {
  if (misPower_ == 1) return pdf / (pdf + other);
  const float a = std::pow(pdf, misPower_), b = std::pow(other, misPower_);
  return a / (a + b);
}

float PathTracer::emissionWeight(bool countedByLightSampling, float bsdfPdf, float lightPdf) const {
  if (!countedByLightSampling) return 1;
  switch (strategy_) {
    case Strategy::Materials:
      return 1;
    case Strategy::NextEvent:
      return 0;
    case Strategy::Mis:
      return lightPdf > 0 ? misWeight(bsdfPdf, lightPdf) : 1;
  }
  return 1;
}

Color3 PathTracer::sampleLight(const Scene& scene, const LightChoice& choice, Sampler& sampler,
                               const SurfaceInteraction& si, const Vector3f& wi,
                               SampleContext& context) const {
  float pmf = 0;
  const Light* light = choice.sample(sampler.next1D(), &pmf);
  const Point2f u = sampler.next2D();
  if (!light || !(pmf > 0)) return Color3::Zero();
  const auto ls = light->sampleLi(si.p, u);
  if (!ls) return Color3::Zero();
  const Vector3f wo = si.toLocal(ls->wi);
  const TextureQuery q = si.textureQuery();
  const Color3 f = si.material->eval(q, wi, wo, TransportMode::Radiance) * std::fabs(wo.z());
  if (isBlack(f)) return Color3::Zero();
  const Ray shadow = ls->atInfinity ? si.spawnRay(ls->wi) : si.spawnRayTo(ls->p, ls->pError, ls->n);
  ++context.stats.rays;
  if (scene.occluded(shadow)) return Color3::Zero();
  const float lightPdf = pmf * ls->pdf;
  const float w = strategy_ == Strategy::Mis ? misWeight(lightPdf, si.material->pdf(q, wi, wo)) : 1;
  return f * ls->radiance * (w / lightPdf);
}

Color3 PathTracer::Li(const Scene& scene, Sampler& sampler, const Ray& cameraRay,
                      SampleContext& context) const {
  Color3 L = Color3::Zero(), beta = Color3::Ones();
  RouletteHistory history;
  Ray ray = cameraRay;
  // Whether emission reached by the current ray could also have been found by sampling a
  // light at the previous vertex (false for camera rays and after delta bounces).
  bool lightSampledBefore = false;
  float bsdfPdf = 0;
  Point3f previous = ray.o;
  // The light choice at the previous vertex, which the MIS weight of a light hit reads.
  LightChoice choice;
  const bool samplesLights = strategy_ != Strategy::Materials;
  // Adds the contribution of paths with `bounces` bounces.
  const auto add = [&](int bounces, const Color3& c) {
    L += c;
    if (context.components) context.components->addPathLength(bounces, c);
  };

  for (int bounce = 0;; ++bounce) {
    SurfaceInteraction si;
    ++context.stats.rays;
    if (!scene.intersect(ray, si)) {
      if (const EnvironmentLight* bg = scene.background()) {
        const float lightPdf = lightSampledBefore ? choice.pmf(bg) * bg->pdfLi(ray.d) : 0;
        add(bounce,
            beta * bg->radiance(ray.d) * emissionWeight(lightSampledBefore, bsdfPdf, lightPdf));
      }
      break;
    }
    if (si.light) {
      const Color3 Le = si.light->radiance(si.ng, -ray.d);
      if (!isBlack(Le)) {
        const float lightPdf =
            lightSampledBefore ? choice.pmf(si.light) * si.light->pdfLi(previous, si.p, si.ng) : 0;
        add(bounce, beta * Le * emissionWeight(lightSampledBefore, bsdfPdf, lightPdf));
      }
    }
    if (bounce >= maxBounces_ || si.material->lobes() == kNoLobe) break;

    const Vector3f wi = si.toLocal(-ray.d);
    const bool canSampleLights = samplesLights && si.material->hasNonDeltaLobe();
    if (canSampleLights) {
      choice = scene.lightChoice(si.p);
      add(bounce + 1, beta * sampleLight(scene, choice, sampler, si, wi, context));
    }

    const float uLobe = sampler.next1D();
    const auto bs = si.material->sample(si.textureQuery(), wi, uLobe, sampler.next2D(),
                                        TransportMode::Radiance);
    if (!bs) break;
    beta *= bs->weight;
    history.record(*bs, TransportMode::Radiance);
    lightSampledBefore = canSampleLights && !bs->isDelta();
    bsdfPdf = bs->pdf;
    previous = si.p;
    ray = si.spawnRay(si.toWorld(bs->wo));

    float survival;
    if (!roulette_.survives(history, beta, sampler, &survival)) break;
    beta /= survival;
  }
  return L;
}

}  // namespace verity
