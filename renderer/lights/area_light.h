// A shape with a diffuse-light material: constant radiance from its front side.
#pragma once

#include "lights/light.h"
#include "shapes/shape.h"

namespace verity {

class AreaLight : public Light {
 public:
  AreaLight(const Shape& shape, const Color3& radiance) : shape_(shape), radiance_(radiance) {}

  std::optional<LightSample> sampleLi(const Point3f& ref, const Point2f& u) const override;
  // Density of sampleLi choosing point p (normal n) seen from ref.
  float pdfLi(const Point3f& ref, const Point3f& p, const Normal3f& n) const;
  // Radiance leaving point with front normal n in direction w.
  Color3 radiance(const Normal3f& n, const Vector3f& w) const {
    return n.dot(w) > 0 ? radiance_ : Color3::Zero();
  }
  // Emission for light subpaths: a point uniform by area, a cosine-distributed direction on
  // the front side.
  std::optional<LightEmission> sampleLe(const Point2f& uPos, const Point2f& uDir,
                                        const Point3f& sceneCenter,
                                        float sceneRadius) const override;
  // Densities of sampleLe choosing a point (per area) and direction w there (per solid angle;
  // 0 behind the front normal n).
  void pdfLe(const Normal3f& n, const Vector3f& w, float* pdfPos, float* pdfDir) const;
  double power(double sceneRadius) const override {
    return double{luminance(radiance_)} * kPi * shape_.area();
  }
  double contributionEstimate(const Point3f& ref) const override {
    return double{luminance(radiance_)} * shape_.solidAngleEstimate(ref);
  }
  const Shape& shape() const { return shape_; }

 private:
  const Shape& shape_;
  Color3 radiance_;
};

}  // namespace verity
