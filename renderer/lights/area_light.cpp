#include "lights/area_light.h"

#include "core/frame.h"
#include "sampling/warp.h"

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
  ls.pError = s->pError;
  ls.pdf = s->pdf;
  ls.radiance = radiance(s->n, -ls.wi);
  if (isBlack(ls.radiance)) return std::nullopt;
  return ls;
}

float AreaLight::pdfLi(const Point3f& ref, const Point3f& p, const Normal3f& n) const {
  return shape_.pdfSolidAngle(ref, p, n);
}

std::optional<LightEmission> AreaLight::sampleLe(const Point2f& uPos, const Point2f& uDir,
                                                 const Point3f&, float) const {
  const ShapeSample s = shape_.sampleArea(uPos);
  const Vector3f local = warp::squareToCosineHemisphere(uDir);
  if (!(local.z() > 0) || !(s.pdf > 0)) return std::nullopt;
  LightEmission e;
  e.p = s.p;
  e.n = s.n;
  e.pError = s.pError;
  e.d = Frame(s.n).toWorld(local).normalized();
  e.pdfPos = s.pdf;
  e.pdfDir = warp::squareToCosineHemispherePdf(local);
  e.radiance = radiance(s.n, e.d);
  if (isBlack(e.radiance) || !(e.pdfDir > 0)) return std::nullopt;
  return e;
}

void AreaLight::pdfLe(const Normal3f& n, const Vector3f& w, float* pdfPos, float* pdfDir) const {
  *pdfPos = 1.0f / shape_.area();
  *pdfDir = std::max(0.0f, n.dot(w)) * kInvPi;
}

}  // namespace verity
