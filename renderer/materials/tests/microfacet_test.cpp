// The microfacet distributions: normalisation, consistency of Λ with D, guards.
#include "materials/microfacet.h"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "materials/tests/material_test_util.h"

namespace verity::test {
namespace {

using boost::math::quadrature::gauss_kronrod;
constexpr double kPiD = 3.14159265358979323846;

Vector3f sphericalDirection(double theta, double phi) {
  return Vector3f(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                  float(std::cos(theta)));
}

// ∫ f(θ) dθ over [0, π/2], split where the lobe of width α ends so that the adaptive rule
// sees the peak.
template <class F>
double integrateTheta(F f, double alpha) {
  const double split = std::min(kPiD / 2, 10 * alpha);
  double sum = gauss_kronrod<double, 61>::integrate(f, 0.0, split, 10, 1e-8);
  if (split < kPiD / 2) sum += gauss_kronrod<double, 61>::integrate(f, split, kPiD / 2, 10, 1e-8);
  return sum;
}

const MicrofacetType kTypes[] = {MicrofacetType::Beckmann, MicrofacetType::GGX};

// ∫ D(m) cos θm dωm = 1: the projected area of the microsurface is that of the macrosurface.
TEST(Microfacet, ProjectedAreaIsOne) {
  for (MicrofacetType type : kTypes) {
    for (float alpha : {0.01f, 0.1f, 0.3f, 0.6f, 1.0f}) {
      const MicrofacetDistribution d(type, alpha);
      const double integral =
          2 * kPiD *
          integrateTheta(
              [&](double t) {
                return double(d.D(sphericalDirection(t, 0.3))) * std::cos(t) * std::sin(t);
              },
              alpha);
      EXPECT_NEAR(integral, 1.0, 1e-3) << "type " << int(type) << " alpha " << alpha;
    }
  }
}

// ∫ G1(wi, m) max(0, wi·m) D(m) dωm = cos θi (Heitz 2014, eq. 2 with Smith's G1): the
// visible-normal density integrates to 1. Fails when Λ does not belong to D.
TEST(Microfacet, VisibleNormalsIntegrateToOne) {
  for (MicrofacetType type : kTypes) {
    for (float alpha : {0.1f, 0.5f, 1.0f}) {
      for (double thetaI : {0.0, 45.0, 80.0, 89.0}) {
        const MicrofacetDistribution d(type, alpha);
        const Vector3f wi = direction(thetaI, 0.4);
        auto inner = [&](double theta) {
          // The trapezoid rule in φ (periodic integrand; only the max(0, wi·m) kink limits
          // its accuracy, to far below the tolerance with 1,024 points).
          const int n = 1024;
          double sum = 0;
          for (int k = 0; k < n; ++k)
            sum += d.pdfNormal(wi, sphericalDirection(theta, 2 * kPiD * (k + 0.5) / n));
          return sum * (2 * kPiD / n) * std::sin(theta);
        };
        // Fixed 64-point Gauss-Legendre rules in θ on both sides of the lobe's edge.
        using boost::math::quadrature::gauss;
        const double split = std::min(kPiD / 2, 10.0 * alpha);
        double integral = gauss<double, 64>::integrate(inner, 0.0, split);
        if (split < kPiD / 2) integral += gauss<double, 64>::integrate(inner, split, kPiD / 2);
        EXPECT_NEAR(integral, 1.0, 2e-3)
            << "type " << int(type) << " alpha " << alpha << " theta " << thetaI;
      }
    }
  }
}

// Λ for Beckmann against values of the exact formula computed independently in double
// precision, and GGX's closed form.
TEST(Microfacet, LambdaMatchesClosedForms) {
  for (double thetaDeg : {10.0, 45.0, 70.0, 85.0}) {
    const Vector3f v = direction(thetaDeg);
    const double tanT = std::tan(thetaDeg * kPiD / 180);
    for (double alpha : {0.2, 0.7}) {
      const double a = 1 / (alpha * tanT);
      const double beckmann = 0.5 * (std::erf(a) - 1 + std::exp(-a * a) / (a * std::sqrt(kPiD)));
      const double ggx = 0.5 * (-1 + std::sqrt(1 + alpha * alpha * tanT * tanT));
      EXPECT_NEAR(MicrofacetDistribution(MicrofacetType::Beckmann, float(alpha)).Lambda(v),
                  beckmann, 1e-4 * (1 + beckmann));
      EXPECT_NEAR(MicrofacetDistribution(MicrofacetType::GGX, float(alpha)).Lambda(v), ggx,
                  1e-4 * (1 + ggx));
    }
  }
}

// GGX's D, G1 and reflection G2, which the distribution evaluates without tan θ, against the
// textbook forms in long double: D = 1/(π α² cos⁴θ (1 + tan²θ/α²)²) (Walter et al. 2007,
// eq. 33), G1 = 1/(1 + Λ) and G2 = 1/(1 + Λ(wi) + Λ(wo)) with Λ = (√(1 + α² tan²θ) − 1)/2
// (Heitz 2014, eq. 72), from the roughest α to the smoothest and out to grazing directions.
TEST(Microfacet, GgxTermsMatchTheirTextbookForms) {
  using Vec3d = Eigen::Vector3d;
  const auto dir = [](long double thetaDeg, long double phi) {
    const long double t = thetaDeg * kPiD / 180;
    return Vec3d(double(std::sin(t) * std::cos(phi)), double(std::sin(t) * std::sin(phi)),
                 double(std::cos(t)));
  };
  const auto tan2 = [](const Vec3d& v) {
    return ((long double)v.x() * v.x() + (long double)v.y() * v.y()) / ((long double)v.z() * v.z());
  };
  for (float alpha : {1e-4f, 0.01f, 0.3f, 1.0f, 4.0f}) {
    const MicrofacetDistribution d(MicrofacetType::GGX, alpha);
    const long double a2 = (long double)alpha * alpha;
    const auto lambda = [&](const Vec3d& v) { return (std::sqrt(1 + a2 * tan2(v)) - 1) / 2; };
    for (double thetaI : {0.0, 30.0, 60.0, 85.0, 89.9}) {
      const Vec3d wi = dir(thetaI, 0.3);
      for (double thetaM : {0.0, 1e-3, 1.0, 20.0, 50.0, 80.0}) {
        const Vec3d m = dir(thetaM, 0.5);
        const long double c2 = (long double)m.z() * m.z(), t = 1 + tan2(m) / a2;
        const long double dExpected = 1 / (kPiD * a2 * c2 * c2 * t * t);
        EXPECT_NEAR(d.D(m), double(dExpected), 1e-12 * double(dExpected))
            << "alpha " << alpha << " theta_m " << thetaM;
        if (wi.dot(m) > 0)
          EXPECT_NEAR(d.G1(wi, m), double(1 / (1 + lambda(wi))), 1e-13)
              << "alpha " << alpha << " theta_i " << thetaI << " theta_m " << thetaM;
      }
      for (double thetaO : {0.0, 45.0, 88.0, 89.99}) {
        const Vec3d wo = dir(thetaO, 2.0), h = (wi + wo).normalized();
        EXPECT_NEAR(d.G2(wi, wo, h), double(1 / (1 + lambda(wi) + lambda(wo))), 1e-13)
            << "alpha " << alpha << " theta_i " << thetaI << " theta_o " << thetaO;
      }
    }
  }
}

// The guards: no NaN or Inf at α = 1e-4 (and below, clamped), wi.z = 0, 89.99°, for
// extreme sample values, and D = 0 where cos⁴θ underflows.
TEST(Microfacet, GuardsAtDegenerateInputs) {
  const std::vector<Vector3f> dirs = {Vector3f(0, 0, 1), Vector3f(1, 0, 0), direction(89.99),
                                      direction(60), Vector3f(0.6f, 0.8f, 1e-20f)};
  const std::vector<Point2f> us = {Point2f(0, 0), Point2f(kOneMinusEpsilon, kOneMinusEpsilon),
                                   Point2f(0, kOneMinusEpsilon), Point2f(0.5f, 0.5f),
                                   Point2f(kOneMinusEpsilon, 0.25f)};
  for (MicrofacetType type : kTypes) {
    for (auto sampling : {MicrofacetSampling::Normals, MicrofacetSampling::Visible}) {
      for (float alpha : {0.0f, 1e-6f, 1e-4f, 0.5f, 1.0f, 4.0f}) {
        const MicrofacetDistribution d(type, alpha, sampling);
        EXPECT_GE(d.alpha(), MicrofacetDistribution::kMinAlpha);
        for (const Vector3f& wi : dirs) {
          EXPECT_FALSE(std::isnan(d.Lambda(wi)));
          EXPECT_GE(d.Lambda(wi), 0.0f);
          for (const Vector3f& wo : dirs) {
            const float g2 = d.G2(wi, wo, Vector3f(0, 0, 1));
            EXPECT_TRUE(std::isfinite(g2) && g2 >= 0 && g2 <= 1);
          }
          for (const Point2f& u : us) {
            const Vector3f m = d.sampleNormal(wi, u);
            ASSERT_TRUE(m.allFinite());
            EXPECT_NEAR(m.norm(), 1.0f, 1e-5f);
            EXPECT_GE(m.z(), 0.0f);
            const float dm = d.D(m), p = d.pdfNormal(wi, m), g1 = d.G1(wi, m);
            EXPECT_TRUE(std::isfinite(dm) && dm >= 0);
            EXPECT_TRUE(std::isfinite(p) && p >= 0);
            EXPECT_TRUE(std::isfinite(g1) && g1 >= 0 && g1 <= 1);
          }
        }
        // Directions in the tangent plane have infinite Λ and zero masking.
        EXPECT_EQ(d.G1(Vector3f(1, 0, 0), Vector3f(0, 0, 1)), 0.0f);
        EXPECT_EQ(
            d.D(Vector3f(1, 0, 1e-12f).normalized()),
            type == MicrofacetType::Beckmann ? 0.0f : d.D(Vector3f(1, 0, 1e-12f).normalized()));
      }
    }
  }
}

// Visible normals are visible: every sampled m faces wi, for all incidences.
TEST(Microfacet, VisibleSamplesFaceTheViewer) {
  Rng rng(11);
  for (MicrofacetType type : kTypes) {
    for (float alpha : {1e-4f, 0.1f, 1.0f}) {
      const MicrofacetDistribution d(type, alpha, MicrofacetSampling::Visible);
      for (double theta : incidenceAngles()) {
        const Vector3f wi = direction(theta);
        for (int i = 0; i < 2000; ++i) {
          const Vector3f m = d.sampleNormal(wi, rng.next2());
          ASSERT_GE(wi.dot(m), -1e-6f) << "alpha " << alpha << " theta " << theta;
        }
      }
    }
  }
}

}  // namespace
}  // namespace verity::test
