// The background: radiance arriving from infinity along every direction a ray escapes to,
// constant or a lat-long image. Image backgrounds are importance-sampled by luminance.
#pragma once

#include <memory>

#include "lights/light.h"
#include "sampling/distribution.h"
#include "textures/image_texture.h"

namespace verity {

class EnvironmentLight : public Light {
 public:
  explicit EnvironmentLight(const Color3& constant);
  explicit EnvironmentLight(std::shared_ptr<const ImageTexture> image);

  // Radiance arriving along -d, for a ray escaping in direction d.
  Color3 radiance(const Vector3f& d) const;
  std::optional<LightSample> sampleLi(const Point3f& ref, const Point2f& u) const override;
  float pdfLi(const Vector3f& d) const;
  // Emission for light subpaths: a direction towards the environment chosen as sampleLi
  // does (so both strategies share one directional density), then a parallel ray travelling
  // back into the scene from a disk of radius sceneRadius, perpendicular to it, centred on
  // sceneCenter + sceneRadius · direction (pbrt-v3 §16.1.5).
  std::optional<LightEmission> sampleLe(const Point2f& uPos, const Point2f& uDir,
                                        const Point3f& sceneCenter,
                                        float sceneRadius) const override;
  // Densities of sampleLe for the ray arriving from direction `towardsEnvironment`: per area
  // on the disk, per solid angle of the direction.
  void pdfLe(const Vector3f& towardsEnvironment, float sceneRadius, float* pdfPos,
             float* pdfDir) const;
  double power(double sceneRadius) const override;
  // Its mean luminance over the hemisphere above a surface.
  double contributionEstimate(const Point3f&) const override {
    return double{luminance(average_)} * 2 * kPi;
  }
  bool isInfinite() const override { return true; }
  bool isBlackEverywhere() const { return !image_ && isBlack(constant_); }

  // Lat-long map: u along azimuth (from −z towards +x), v from +y (top row) to −y.
  static Point2f directionToUv(const Vector3f& d);
  static Vector3f uvToDirection(const Point2f& uv);

 private:
  Color3 constant_ = Color3::Zero();
  std::shared_ptr<const ImageTexture> image_;
  Distribution2D distribution_;
  Color3 average_ = Color3::Zero();
};

}  // namespace verity
