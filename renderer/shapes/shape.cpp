#include "shapes/shape.h"

namespace verity {

float areaToSolidAngle(float pdfArea, const Point3f& ref, const Point3f& p, const Normal3f& n) {
  const Vector3f d = p - ref;
  const float dist2 = d.squaredNorm();
  if (!(dist2 > 0)) return 0;
  const float cosTheta = std::fabs(n.dot(d)) / std::sqrt(dist2);
  if (!(cosTheta > 0)) return 0;
  const float pdf = pdfArea * dist2 / cosTheta;
  return std::isfinite(pdf) ? pdf : 0;
}

std::optional<ShapeSample> Shape::sampleSolidAngle(const Point3f& ref, const Point2f& u) const {
  ShapeSample s = sampleArea(u);
  s.pdf = areaToSolidAngle(s.pdf, ref, s.p, s.n);
  if (!(s.pdf > 0)) return std::nullopt;
  return s;
}

float Shape::pdfSolidAngle(const Point3f& ref, const Point3f& p, const Normal3f& n) const {
  return areaToSolidAngle(1.0f / area(), ref, p, n);
}

}  // namespace verity
