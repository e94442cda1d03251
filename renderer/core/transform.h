// An affine transform with its inverse, applied to points, vectors and normals.
#pragma once

#include "core/math.h"

namespace verity {

class Transform {
 public:
  Transform() : m_(Matrix4f::Identity()), inv_(Matrix4f::Identity()) {}
  explicit Transform(const Matrix4f& m) : m_(m), inv_(m.inverse()) {}
  Transform(const Matrix4f& m, const Matrix4f& inv) : m_(m), inv_(inv) {}

  const Matrix4f& matrix() const { return m_; }
  const Matrix4f& inverseMatrix() const { return inv_; }
  Transform inverse() const { return Transform(inv_, m_); }
  Transform operator*(const Transform& t) const { return Transform(m_ * t.m_, t.inv_ * inv_); }

  Point3f point(const Point3f& p) const {
    return m_.topLeftCorner<3, 3>() * p + m_.topRightCorner<3, 1>();
  }
  Vector3f vector(const Vector3f& v) const { return m_.topLeftCorner<3, 3>() * v; }
  // Normals transform by the inverse transpose; the result is not normalised.
  Normal3f normal(const Normal3f& n) const { return inv_.topLeftCorner<3, 3>().transpose() * n; }

  // Whether the linear part is a rotation times a uniform scale (returned in `scale`).
  bool isSimilarity(float* scale) const;
  // Whether the transform mirrors (negative determinant).
  bool flipsHandedness() const { return m_.topLeftCorner<3, 3>().determinant() < 0; }
  bool isInvertible() const;

 private:
  Matrix4f m_, inv_;
};

}  // namespace verity
