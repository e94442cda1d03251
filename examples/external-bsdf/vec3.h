// The example renderer's own vector and colour types: nothing from Verity.
#pragma once

#include <cmath>

namespace example {

constexpr double kPi = 3.14159265358979323846;

struct Vec3 {
  double x = 0, y = 0, z = 0;
};
inline Vec3 operator+(const Vec3& a, const Vec3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator*(double s, const Vec3& v) {
  return {s * v.x, s * v.y, s * v.z};
}
inline double dot(const Vec3& a, const Vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 normalize(const Vec3& v) {
  return (1 / std::sqrt(dot(v, v))) * v;
}

struct Vec2 {
  double x = 0, y = 0;
};

struct Rgb {
  double r = 0, g = 0, b = 0;
};

}  // namespace example
