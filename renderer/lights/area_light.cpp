#include "lights/area_light.h"

namespace verity {

std::optional<LightSample> AreaLight::sampleLi(const Point3f& ref, const Point2f& u) const {
  auto s = shape_.sampleSolidAngle(ref, u);
  if (!s) return std::nullopt;
  const Vector3f d = s->p - ref;
  const float dist = d.norm();
  if (!(dist > 0) || !(s->pdf > 0)) return std::nullopt;
  LightSample ls;
  ls.wi = d / dist;
  ls.p = s->p;
  ls.n = s->n;
  ls.pdf = s->pdf;
  ls.radiance = radiance(s->n, -ls.wi);
  if (isBlack(ls.radiance)) return std::nullopt;
  return ls;
}

float AreaLight::pdfLi(const Point3f& ref, const Point3f& p, const Normal3f& n) const {
  return shape_.pdfSolidAngle(ref, p, n);
}

}  // namespace verity
