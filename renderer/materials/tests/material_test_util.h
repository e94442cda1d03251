// Helpers shared by the material tests: building materials from JSON, fixed-seed random
// numbers and directions, and the statistics of Monte Carlo estimates.
#pragma once

#include <cmath>
#include <memory>
#include <pcg_random.hpp>
#include <string>
#include <vector>

#include "materials/material_factory.h"
#include "sampling/independent_sampler.h"
#include "sampling/warp.h"

namespace verity::test {

// Parses one material object, e.g. R"({"type": "ggx", "ab": 0.3})".
inline std::shared_ptr<const Material> makeMaterial(const std::string& json) {
  static TextureFactory textures;
  std::vector<VerityError> warnings;  // the grids test albedos of 1 and below
  MaterialFactory factory(textures, warnings);
  return factory.make(JsonNode::parse(json, "test.json"));
}

class Rng {
 public:
  explicit Rng(uint64_t seed) : rng_(seed) {}
  float next() { return uniformFloat(rng_()); }
  Point2f next2() {
    const float x = next();
    return {x, next()};
  }

 private:
  pcg32 rng_;
};

// A unit direction at `thetaDeg` from +z, azimuth `phi` (radians); negative z when `below`.
inline Vector3f direction(double thetaDeg, double phi = 0.7, bool below = false) {
  const double t = thetaDeg * 3.14159265358979323846 / 180.0;
  Vector3f v(float(std::sin(t) * std::cos(phi)), float(std::sin(t) * std::sin(phi)),
             float(std::cos(t)));
  v.normalize();
  if (below) v.z() = -v.z();
  return v;
}

// The hard incidence angles: normal, moderate, grazing and almost tangent.
inline const std::vector<double>& incidenceAngles() {
  static const std::vector<double> angles = {0.0, 30.0, 60.0, 85.0, 89.0, 89.99};
  return angles;
}

// Running mean and standard error of a Monte Carlo estimate (Welford's update).
class MeanEstimate {
 public:
  void add(double x) {
    ++n_;
    const double d = x - mean_;
    mean_ += d / double(n_);
    m2_ += d * (x - mean_);
  }
  double mean() const { return mean_; }
  double standardError() const {
    return n_ > 1 ? std::sqrt(m2_ / double(n_ - 1) / double(n_)) : 0.0;
  }
  long count() const { return n_; }

 private:
  long n_ = 0;
  double mean_ = 0, m2_ = 0;
};

// Number of standard errors for the one-sided bounds of the statistical tests. At 4.5 one
// check falsely fails with probability 3.4e-6; the materials suite makes a few thousand
// such checks, so the whole suite falsely fails with probability below 1%.
inline constexpr double kSigmas = 4.5;

// |a − b| relative to the larger magnitude, or to `floor` when both are smaller (values
// near the denormal range carry no relative precision).
inline float relativeError(float a, float b, float floor = 1e-12f) {
  const float scale = std::max({std::abs(a), std::abs(b), floor});
  return scale > 0 ? std::abs(a - b) / scale : 0.0f;
}

}  // namespace verity::test
