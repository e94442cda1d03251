// Spatially varying parameters. A constant parameter is stored inline so that it costs no
// lookup and no virtual call.
#pragma once

#include <memory>

#include "core/math.h"

namespace verity {

// Where a texture is looked up: surface parameterisation and world position.
struct TextureQuery {
  Point2f uv = Point2f::Zero();
  Point3f p = Point3f::Zero();
};

class Texture {
 public:
  virtual ~Texture() = default;
  virtual Color3 eval(const TextureQuery& q) const = 0;
  // The largest value any channel can take anywhere.
  virtual float upperBound() const = 0;
};

// A texture-valued material parameter.
class TexturedColor {
 public:
  TexturedColor() = default;
  explicit TexturedColor(const Color3& value) : value_(value) {}
  explicit TexturedColor(std::shared_ptr<const Texture> texture) : texture_(std::move(texture)) {}

  Color3 eval(const TextureQuery& q) const { return texture_ ? texture_->eval(q) : value_; }
  // Scalar parameters (roughness, blend amount) read the mean of the channels.
  float evalScalar(const TextureQuery& q) const { return eval(q).mean(); }
  bool isConstant() const { return !texture_; }
  float upperBound() const { return texture_ ? texture_->upperBound() : value_.maxCoeff(); }
  // Only meaningful when isConstant().
  const Color3& constant() const { return value_; }

 private:
  Color3 value_ = Color3::Zero();
  std::shared_ptr<const Texture> texture_;
};

}  // namespace verity
