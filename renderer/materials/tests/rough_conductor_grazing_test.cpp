// The rough conductor's density at grazing incidence, where wo near −wi makes the half
// vector's wi·h a difference of nearly equal numbers.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "materials/tests/material_test_util.h"

namespace verity {
namespace {

// The density of D(m) cos θm sampling mapped to wo by reflection (Walter et al. 2007, eq.
// 14: pdf = D(h) cos θh / (4 wi·h)), in double precision from the unit vectors the float
// inputs stand for, with D of Walter et al. 2007, eqs. 25 (Beckmann) and 33 (GGX).
double referencePdf(bool ggx, double alpha, const Vector3f& wiF, const Vector3f& woF) {
  const Eigen::Vector3d wi = wiF.cast<double>().normalized(), wo = woF.cast<double>().normalized();
  const Eigen::Vector3d h = (wi + wo).normalized();
  const double cos2 = h.z() * h.z(), tan2 = (1 - cos2) / cos2, a2 = alpha * alpha;
  const double d =
      ggx ? 1 / (std::numbers::pi * a2 * cos2 * cos2 * (1 + tan2 / a2) * (1 + tan2 / a2))
          : std::exp(-tan2 / a2) / (std::numbers::pi * a2 * cos2 * cos2);
  return d * h.z() / (4 * wi.dot(h));
}

TEST(RoughConductorGrazing, NormalsDensityNearTheAntipodeOfAGrazingWi) {
  // wi at 90° and 89.9999° as single precision makes them (cos 90° = 6.1e-17 in float).
  for (double degrees : {90.0, 89.9999}) {
    const double t = degrees * std::numbers::pi / 180;
    const Vector3f wi(float(std::sin(t)), 0.0f, float(std::cos(t)));
    for (const char* type : {"ggx", "beckmann"}) {
      const auto m = test::makeMaterial(
          fmt::format(R"({{"type":"{}","alpha":0.3,"sampling":"normals"}})", type));
      // wo at angles δ from −wi, above the horizon, towards +y and +z.
      for (double delta : {1e-2, 1e-3, 1e-4, 1e-5}) {
        const Vector3f wo =
            Eigen::Vector3d(-std::cos(delta), delta * 0.6, delta * 0.8).normalized().cast<float>();
        const double expected = referencePdf(type[0] == 'g', 0.3, wi, wo);
        const double pdf = m->pdf(TextureQuery{}, wi, wo);
        EXPECT_NEAR(pdf, expected, 1e-3 * expected)
            << type << " at " << degrees << " deg, delta " << delta;
      }
    }
  }
}

}  // namespace
}  // namespace verity
