#include "integrators/path_vertex.h"

#include "lights/area_light.h"
#include "lights/environment_light.h"

namespace verity {

Vector3f directionTo(const PathVertex& from, const PathVertex& to) {
  if (to.atInfinity()) return to.w;
  if (from.atInfinity()) return -from.w;
  return (to.p() - from.p()).normalized();
}

float toAreaDensity(float pdfSolidAngle, const PathVertex& from, const PathVertex& to) {
  if (to.atInfinity()) return pdfSolidAngle;
  const Vector3f d = to.p() - from.p();
  const float dist2 = d.squaredNorm();
  if (!(dist2 > 0)) return 0;
  float pdf = pdfSolidAngle / dist2;
  if (to.onSurface()) pdf *= std::fabs(to.si.ng.dot(d)) / std::sqrt(dist2);
  return std::isfinite(pdf) ? pdf : 0;
}

Color3 scatterFactor(const PathVertex& v, const Vector3f& towardsCamera,
                     const Vector3f& towardsLight, TransportMode mode) {
  const float cosGeometric = std::fabs(v.si.ng.dot(towardsLight));
  if (!(cosGeometric > 0)) return Color3::Zero();
  const Vector3f toCamera = v.si.toLocal(towardsCamera), toLight = v.si.toLocal(towardsLight);
  const TextureQuery q = v.si.textureQuery();
  // The material's wi is where the walk came from: the camera side for radiance, the light
  // side for importance.
  const Color3 f = mode == TransportMode::Radiance
                       ? v.si.material->eval(q, toCamera, toLight, mode)
                       : v.si.material->eval(q, toLight, toCamera, mode);
  return f * (std::fabs(toLight.z()) / cosGeometric);
}

float scatterPdf(const PathVertex& v, const Vector3f& towardsPrevious,
                 const Vector3f& towardsNext) {
  return v.si.material->pdf(v.si.textureQuery(), v.si.toLocal(towardsPrevious),
                            v.si.toLocal(towardsNext));
}

Color3 emittedRadiance(const PathVertex& v, const Vector3f& d) {
  switch (v.kind) {
    case VertexKind::Environment:
      return static_cast<const EnvironmentLight*>(v.light)->radiance(v.w);
    case VertexKind::Light:
    case VertexKind::Surface:
      return v.si.light ? v.si.light->radiance(v.si.ng, d) : Color3::Zero();
    case VertexKind::Camera:
      break;
  }
  return Color3::Zero();
}

}  // namespace verity
