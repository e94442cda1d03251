#include "integrators/bdpt_subpath.h"

#include "lights/area_light.h"
#include "lights/environment_light.h"

namespace verity {

namespace {

const Light* emitterOf(const PathVertex& v) {
  return v.kind == VertexKind::Surface ? static_cast<const Light*>(v.si.light) : v.light;
}

// Extends `path` (whose last vertex emitted `ray`) until it holds maxVertices vertices, the
// ray escapes, the material absorbs or roulette ends it. `pdfDir` is the density of the
// ray's direction at the last vertex: per solid angle, or for a ray from the environment's
// disk the disk's density per area, projected onto the surface hit.
void randomWalk(const Scene& scene, Sampler& sampler, Ray ray, Color3 beta, float pdfDir,
                TransportMode mode, int maxVertices, const RussianRoulette& roulette,
                std::vector<PathVertex>& path, PathStats& stats) {
  // Throughput of the scattering events alone, for roulette (light subpaths start with the
  // emitted power, which says nothing about how much a path has lost).
  Color3 scattering = Color3::Ones();
  RouletteHistory history;
  while (static_cast<int>(path.size()) < maxVertices) {
    SurfaceInteraction si;
    ++stats.rays;
    if (!scene.intersect(ray, si)) {
      if (mode == TransportMode::Radiance && scene.background()) {
        PathVertex v;
        v.kind = VertexKind::Environment;
        v.w = ray.d;
        v.wPrevious = -ray.d;
        v.light = scene.background();
        v.beta = beta;
        v.pdfFwd = pdfDir;  // per solid angle at infinity
        path.push_back(v);
      }
      return;
    }
    PathVertex v;
    v.kind = VertexKind::Surface;
    v.si = si;
    v.wPrevious = -ray.d;
    v.beta = beta;
    const PathVertex& previous = path.back();
    v.pdfFwd = previous.atInfinity() ? pdfDir * std::fabs(si.ng.dot(ray.d))
                                     : toAreaDensity(pdfDir, previous, v);
    path.push_back(v);
    if (static_cast<int>(path.size()) >= maxVertices || si.material->lobes() == kNoLobe) return;

    PathVertex& current = path.back();
    const Vector3f wiWorld = -ray.d;
    const Vector3f wi = si.toLocal(wiWorld);
    const float uLobe = sampler.next1D();
    const auto bs = si.material->sample(si.textureQuery(), wi, uLobe, sampler.next2D(), mode);
    if (!bs) return;
    const Vector3f wo = si.toWorld(bs->wo);
    Color3 weight = bs->weight;
    float pdfFwd = bs->pdf, pdfRev = si.material->pdf(si.textureQuery(), bs->wo, wi);
    if (bs->isDelta()) {
      current.delta = true;
      pdfFwd = pdfRev = 0;
    }
    if (mode == TransportMode::Importance) {
      // Adjoint shading-normal correction (Veach 1997, §5.3, eq. 5.17):
      // |ω_i · n_s| |ω_o · n_g| / (|ω_i · n_g| |ω_o · n_s|), ω_i towards the light side.
      const float denominator = std::fabs(wiWorld.dot(si.ng)) * std::fabs(bs->wo.z());
      if (!(denominator > 0)) return;
      weight *= std::fabs(wi.z()) * std::fabs(wo.dot(si.ng)) / denominator;
    }
    // The density with which a walk from the other end, arriving here along wo, would
    // have chosen the previous vertex.
    PathVertex& before = path[path.size() - 2];
    before.pdfRev = toAreaDensity(pdfRev, current, before);
    beta *= weight;
    scattering *= weight;
    history.record(*bs, mode);
    if (isBlack(beta) || !beta.allFinite()) return;
    ray = si.spawnRay(wo);
    pdfDir = pdfFwd;
    float survival;
    if (!roulette.survives(history, scattering, sampler, &survival)) return;
    beta /= survival;
    scattering /= survival;
  }
}

}  // namespace

void traceCameraSubpath(const Scene& scene, Sampler& sampler, const Ray& ray, int maxVertices,
                        const RussianRoulette& roulette, std::vector<PathVertex>& path,
                        PathStats& stats) {
  path.clear();
  if (maxVertices < 1) return;
  PathVertex camera;
  camera.kind = VertexKind::Camera;
  camera.si.p = ray.o;
  float pdfPos = 0, pdfDir = 0;
  scene.camera().pdfImportance(ray.o, ray.d, &pdfPos, &pdfDir);
  camera.pdfFwd = pdfPos;
  path.push_back(camera);
  if (!(pdfDir > 0)) return;
  // We·cos θ / (pdfPos·pdfDir) = 1 for an importance normalised as the camera's.
  randomWalk(scene, sampler, ray, Color3::Ones(), pdfDir, TransportMode::Radiance, maxVertices,
             roulette, path, stats);
}

float traceLightSubpath(const Scene& scene, Sampler& sampler, int maxVertices,
                        const RussianRoulette& roulette, std::vector<PathVertex>& path,
                        PathStats& stats) {
  path.clear();
  float pmf = 0;
  const Light* light = scene.sampleLight(sampler.next1D(), &pmf);
  const Point2f uPos = sampler.next2D(), uDir = sampler.next2D();
  if (maxVertices < 1 || !light || !(pmf > 0)) return 0;
  const Bounds3f& bounds = scene.bounds();
  const auto e =
      light->sampleLe(uPos, uDir, 0.5f * (bounds.lo + bounds.hi), scene.boundingRadius());
  if (!e) return 0;
  PathVertex origin;
  origin.light = light;
  Ray ray;
  Color3 beta;
  float pdfNext;
  if (e->atInfinity) {
    origin.kind = VertexKind::Environment;
    origin.w = -e->d;
    origin.pdfFwd = pmf * e->pdfDir;
    // The disk ray reaches its first surface with density pdfPos·|cos θ| per area there, and
    // the geometry term towards infinity is |cos θ|: they cancel.
    beta = e->radiance / (pmf * e->pdfDir * e->pdfPos);
    ray = Ray(e->p, e->d);
    pdfNext = e->pdfPos;
  } else {
    origin.kind = VertexKind::Light;
    origin.si.p = e->p;
    origin.si.ng = e->n;
    origin.si.shading = Frame(e->n);
    origin.si.light = static_cast<const AreaLight*>(light);
    origin.si.pError = e->pError;
    origin.pdfFwd = pmf * e->pdfPos;
    beta = e->radiance * std::fabs(e->n.dot(e->d)) / (pmf * e->pdfPos * e->pdfDir);
    ray = origin.si.spawnRay(e->d);
    pdfNext = e->pdfDir;
  }
  origin.beta = Color3::Constant(1.0f / origin.pdfFwd);
  if (!beta.allFinite() || !origin.beta.allFinite()) return 0;
  path.push_back(origin);
  randomWalk(scene, sampler, ray, beta, pdfNext, TransportMode::Importance, maxVertices, roulette,
             path, stats);
  if (path.size() < 2) return 0;
  float lightPathPdf = 0, nextEventPdf = 0;
  endpointDensities(scene, path[0], &path[1], &lightPathPdf, &nextEventPdf);
  return nextEventPdf;
}

float emissionDensity(const Scene& scene, const PathVertex& emitter, const PathVertex& to) {
  if (emitter.atInfinity()) {
    if (to.atInfinity()) return 0;
    float pdfPos = 0, pdfDir = 0;
    static_cast<const EnvironmentLight*>(emitter.light)
        ->pdfLe(emitter.w, scene.boundingRadius(), &pdfPos, &pdfDir);
    return to.onSurface() ? pdfPos * std::fabs(to.si.ng.dot(emitter.w)) : pdfPos;
  }
  const Light* light = emitterOf(emitter);
  if (!light) return 0;
  float pdfPos = 0, pdfDir = 0;
  static_cast<const AreaLight*>(light)->pdfLe(emitter.si.ng, directionTo(emitter, to), &pdfPos,
                                              &pdfDir);
  return toAreaDensity(pdfDir, emitter, to);
}

void endpointDensities(const Scene& scene, const PathVertex& emitter, const PathVertex* from,
                       float* lightPathPdf, float* nextEventPdf) {
  *lightPathPdf = *nextEventPdf = 0;
  const Light* light = emitterOf(emitter);
  if (!light) return;
  const float pmf = scene.lightPmf(light);
  if (emitter.atInfinity()) {
    // Both strategies choose the direction with the environment's own density.
    const float pdf = pmf * static_cast<const EnvironmentLight*>(light)->pdfLi(emitter.w);
    *lightPathPdf = pdf;
    *nextEventPdf = from ? pdf : 0;
    return;
  }
  const auto* area = static_cast<const AreaLight*>(light);
  float pdfPos = 0, pdfDir = 0;
  area->pdfLe(emitter.si.ng, emitter.si.ng, &pdfPos, &pdfDir);
  *lightPathPdf = pmf * pdfPos;
  if (from)
    *nextEventPdf =
        toAreaDensity(pmf * area->pdfLi(from->p(), emitter.p(), emitter.si.ng), *from, emitter);
}

}  // namespace verity
