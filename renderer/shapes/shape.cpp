#include "shapes/shape.h"

#include <algorithm>
#include <cmath>

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

double planarSolidAngleEstimate(double area, const Point3f& centre, const Normal3f& n,
                                const Point3f& ref) {
  const Eigen::Vector3d d = (ref - centre).cast<double>();
  const double dist2 = d.squaredNorm(), facing = n.cast<double>().dot(d);
  if (!(facing > 0)) return 0;
  return std::min(2 * double{kPi}, area * facing / (dist2 * std::sqrt(dist2)));
}

double Shape::solidAngleEstimate(const Point3f& ref) const {
  const Bounds3f b = bounds();
  if ((ref.array() >= b.lo.array()).all() && (ref.array() <= b.hi.array()).all())
    return 2 * double{kPi};
  const double dist2 = (0.5f * (b.lo + b.hi) - ref).cast<double>().squaredNorm();
  return std::min(2 * double{kPi}, double{area()} / dist2);
}

}  // namespace verity
