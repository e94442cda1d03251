// Basic numeric types shared by the whole renderer (Eigen, single precision for geometry).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace verity {

using Vector2f = Eigen::Vector2f;
using Vector3f = Eigen::Vector3f;
using Point2f = Eigen::Vector2f;
using Point3f = Eigen::Vector3f;
using Normal3f = Eigen::Vector3f;
using Point2i = Eigen::Vector2i;
using Vector2i = Eigen::Vector2i;
using Matrix4f = Eigen::Matrix4f;
using Matrix3f = Eigen::Matrix3f;
using Color3 = Eigen::Array3f;

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 0.31830988618379067154f;
inline constexpr float kInv2Pi = 0.15915494309189533577f;
inline constexpr float kInv4Pi = 0.07957747154594766788f;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Largest float strictly below one: keeps sample values in [0, 1).
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

inline float safeSqrt(float x) {
  return std::sqrt(std::max(x, 0.0f));
}
inline float safeAcos(float x) {
  return std::acos(std::clamp(x, -1.0f, 1.0f));
}
inline float sqr(float x) {
  return x * x;
}
inline float degToRad(float d) {
  return d * (kPi / 180.0f);
}
inline float lerp(float t, float a, float b) {
  return (1 - t) * a + t * b;
}

inline bool isFinite(const Color3& c) {
  return c.allFinite();
}
inline bool isBlack(const Color3& c) {
  return (c == 0.0f).all();
}
inline float luminance(const Color3& c) {
  return 0.212671f * c.x() + 0.715160f * c.y() + 0.072169f * c.z();
}
inline float maxComponent(const Color3& c) {
  return c.maxCoeff();
}

}  // namespace verity
