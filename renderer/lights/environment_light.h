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
  Color3 power(float sceneRadius) const override;
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
