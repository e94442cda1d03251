#include "integrators/bdpt_connect.h"

namespace verity {

Color3 emissionContribution(const std::vector<PathVertex>& camera, int t) {
  const PathVertex& pt = camera[t - 1];
  const bool emits = pt.atInfinity() || (pt.kind == VertexKind::Surface && pt.si.light);
  if (!emits) return Color3::Zero();
  return pt.beta * emittedRadiance(pt, pt.wPrevious);
}

Color3 nextEventContribution(const Scene& scene, Sampler& sampler,
                             const std::vector<PathVertex>& camera, int t, PathVertex& sampled,
                             PathStats& stats) {
  float pmf = 0;
  const Light* light = scene.sampleLight(sampler.next1D(), &pmf);
  const Point2f u = sampler.next2D();
  const PathVertex& pt = camera[t - 1];
  if (!light || !(pmf > 0) || pt.kind != VertexKind::Surface || !pt.connectible())
    return Color3::Zero();
  const auto ls = light->sampleLi(pt.p(), u);
  if (!ls) return Color3::Zero();
  const Color3 f = scatterFactor(pt, pt.wPrevious, ls->wi, TransportMode::Radiance) *
                   std::fabs(pt.si.ng.dot(ls->wi));
  const Color3 contribution = pt.beta * f * ls->radiance / (pmf * ls->pdf);
  if (isBlack(contribution)) return Color3::Zero();
  sampled = PathVertex();
  sampled.light = light;
  if (ls->atInfinity) {
    sampled.kind = VertexKind::Environment;
    sampled.w = ls->wi;
  } else {
    sampled.kind = VertexKind::Light;
    sampled.si.p = ls->p;
    sampled.si.ng = ls->n;
    sampled.si.shading = Frame(ls->n);
    sampled.si.light = static_cast<const AreaLight*>(light);
    sampled.si.pError = ls->pError;
  }
  const Ray shadow = ls->atInfinity ? pt.si.spawnRay(ls->wi) : pt.si.spawnRayTo(sampled.si);
  ++stats.rays;
  if (scene.occluded(shadow)) return Color3::Zero();
  return contribution;
}

Color3 edgeContribution(const Scene& scene, const std::vector<PathVertex>& camera, int t,
                        const std::vector<PathVertex>& light, int s, PathStats& stats) {
  const PathVertex &pt = camera[t - 1], &qs = light[s - 1];
  if (!pt.connectible() || !qs.connectible()) return Color3::Zero();
  const Vector3f d = qs.p() - pt.p();
  const float dist2 = d.squaredNorm();
  if (!(dist2 > 0)) return Color3::Zero();
  const Vector3f dir = d / std::sqrt(dist2);
  const Color3 fCamera = scatterFactor(pt, pt.wPrevious, dir, TransportMode::Radiance);
  if (isBlack(fCamera)) return Color3::Zero();
  const Color3 fLight = scatterFactor(qs, -dir, qs.wPrevious, TransportMode::Importance);
  // Geometry term with geometric cosines (the shading cosines are in the factors).
  const float g = std::fabs(pt.si.ng.dot(dir)) * std::fabs(qs.si.ng.dot(dir)) / dist2;
  const Color3 contribution = pt.beta * fCamera * g * fLight * qs.beta;
  if (isBlack(contribution)) return Color3::Zero();
  ++stats.rays;
  if (scene.occluded(pt.si.spawnRayTo(qs.si))) return Color3::Zero();
  return contribution;
}

Color3 cameraContribution(const Scene& scene, Sampler& sampler,
                          const std::vector<PathVertex>& light, int s, PathVertex& sampled,
                          Point2f& film, PathStats& stats) {
  const Point2f u = sampler.next2D();
  const PathVertex& qs = light[s - 1];
  if (!qs.connectible()) return Color3::Zero();
  const auto cs = scene.camera().sampleImportance(qs.p(), u);
  if (!cs) return Color3::Zero();
  const Vector3f& dir = cs->wi;
  // The light endpoint's throughput is 1 / (its density); its emission is evaluated here.
  const Color3 f = s == 1 ? emittedRadiance(qs, dir)
                          : scatterFactor(qs, dir, qs.wPrevious, TransportMode::Importance);
  // We · G / (lens density per area) = We · |cos θ_q| / (density per solid angle at q).
  const Color3 contribution =
      qs.beta * f * (std::fabs(qs.si.ng.dot(dir)) * cs->importance / cs->pdf);
  if (isBlack(contribution)) return Color3::Zero();
  Ray shadow = qs.si.spawnRay(dir);
  shadow.tmax = cs->distance * (1 - 1e-4f);
  ++stats.rays;
  if (scene.occluded(shadow)) return Color3::Zero();
  sampled = PathVertex();
  sampled.kind = VertexKind::Camera;
  sampled.si.p = cs->lensPoint;
  film = cs->film;
  return contribution;
}

Color3 backgroundCameraContribution(const Scene& scene, Sampler& sampler,
                                    const std::vector<PathVertex>& light, Point2f& film,
                                    PathStats& stats) {
  const Point2f u = sampler.next2D();
  const PathVertex& origin = light[0];
  if (!origin.atInfinity()) return Color3::Zero();
  const auto cs = scene.camera().sampleImportanceFromInfinity(origin.w, u);
  if (!cs) return Color3::Zero();
  // As in cameraContribution, with the geometry term towards infinity reduced to the lens
  // cosine, which cs->pdf (per area perpendicular to the direction) holds.
  const Color3 contribution =
      origin.beta * emittedRadiance(origin, origin.w) * cs->importance / cs->pdf;
  if (isBlack(contribution)) return Color3::Zero();
  ++stats.rays;
  if (scene.occluded(Ray(cs->lensPoint, origin.w))) return Color3::Zero();
  film = cs->film;
  return contribution;
}

}  // namespace verity
