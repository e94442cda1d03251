#include "materials/fresnel.h"

#include <gtest/gtest.h>

#include <complex>

#include "materials/tests/material_test_util.h"

namespace verity::test {
namespace {

TEST(Fresnel, DielectricNormalIncidence) {
  for (float eta : {1.5f, 2.4f, 1 / 2.4f, 1.0001f}) {
    const float r0 = sqr((eta - 1) / (eta + 1));
    EXPECT_NEAR(fresnelDielectric(1.0f, eta), r0, 1e-6f);
    EXPECT_NEAR(fresnelDielectric(-1.0f, eta), r0, 1e-6f);  // from inside: same value
  }
}

// Beyond the critical angle from the denser side everything reflects; at exactly grazing
// incidence everything reflects; an index-matched interface transmits everything else.
TEST(Fresnel, DielectricTotalInternalReflectionAndLimits) {
  const float eta = 1.5f;
  const float cosCritical = std::sqrt(1 - 1 / (eta * eta));
  EXPECT_EQ(fresnelDielectric(-(cosCritical - 1e-3f), eta), 1.0f);
  EXPECT_LT(fresnelDielectric(-(cosCritical + 1e-2f), eta), 1.0f);
  EXPECT_EQ(fresnelDielectric(0.0f, eta), 1.0f);
  EXPECT_EQ(fresnelDielectric(0.0f, 1.0f), 1.0f);
  EXPECT_NEAR(fresnelDielectric(0.5f, 1.0f), 0.0f, 1e-7f);
}

// Reflectance is the same from both sides of an interface for a pair of angles related by
// Snell's law (the basis of reciprocity for refraction). cos θt comes from double precision;
// near the critical angle F read from the denser side is ill-conditioned (dF/dcos θ is
// unbounded there), so the angles stop short of it.
TEST(Fresnel, DielectricSymmetricAcrossInterface) {
  for (float eta : {1.5f, 2.4f, 1.0001f, 0.9999f}) {
    for (float cosI : {1.0f, 0.8f, 0.3f, 0.1f}) {
      const double sin2T = (1.0 - double(cosI) * cosI) / (double(eta) * eta);
      if (sin2T >= 0.98) continue;
      const float cosT = float(std::sqrt(1.0 - sin2T));
      EXPECT_NEAR(fresnelDielectric(cosI, eta), fresnelDielectric(-cosT, eta), 1e-4f)
          << eta << " " << cosI;
    }
  }
}

// With zero extinction the conductor formula is the dielectric one.
TEST(Fresnel, ConductorWithoutExtinctionIsDielectric) {
  for (float eta : {1.5f, 2.4f}) {
    for (float cosI : {1.0f, 0.7f, 0.2f, 0.01f}) {
      EXPECT_NEAR(fresnelConductor(cosI, Color3::Constant(eta), Color3::Zero()).x(),
                  fresnelDielectric(cosI, eta), 1e-5f);
    }
  }
}

// Normal incidence: ((n−1)² + k²)/((n+1)² + k²); values stay in [0, 1] at every angle.
TEST(Fresnel, ConductorValues) {
  const Color3 eta(0.05f, 0.2f, 1.5f), k(3.9f, 2.0f, 7.0f);
  const Color3 f = fresnelConductor(1.0f, eta, k);
  for (int c = 0; c < 3; ++c) {
    const float expected = (sqr(eta[c] - 1) + sqr(k[c])) / (sqr(eta[c] + 1) + sqr(k[c]));
    EXPECT_NEAR(f[c], expected, 1e-5f);
  }
  for (float cosI : {-0.5f, 0.0f, 1e-6f, 0.3f, 1.0f, 1.5f}) {
    const Color3 r = fresnelConductor(cosI, eta, k);
    EXPECT_TRUE(r.allFinite() && (r >= 0).all() && (r <= 1).all());
  }
  EXPECT_TRUE((fresnelConductor(0.0f, eta, k) == 1.0f).all());
  EXPECT_EQ(fresnelConductor(0.0f, Color3::Ones(), Color3::Zero()).x(), 1.0f);
}

// The reflectance against the complex Fresnel equations evaluated in double precision
// (Born and Wolf §14.2: cos θt from Snell's law with the complex index), over indices and
// extinctions from index-matched to strongly absorbing, at every incidence. The float
// evaluation errs by up to 1.2·10⁻⁴ near the critical angle of η = 0.999; 2·10⁻⁴ holds it
// there and fails a form whose a² cancels (6·10⁻⁴ at η = k = 0.01).
TEST(Fresnel, ConductorAgreesWithTheComplexEquationsInDouble) {
  auto reference = [](double cosI, double eta, double k) {
    using C = std::complex<double>;
    const C n(eta, k), cosT = std::sqrt(C(1.0) - (1 - cosI * cosI) / (n * n));
    const double rs = std::norm((C(cosI) - n * cosT) / (C(cosI) + n * cosT));
    const double rp = std::norm((n * C(cosI) - cosT) / (n * C(cosI) + cosT));
    return 0.5 * (rs + rp);
  };
  for (float eta : {0.01f, 0.05f, 0.2f, 0.999f, 1.001f, 1.5f, 10.0f, 100.0f})
    for (float k : {0.0f, 1e-4f, 0.01f, 1.0f, 3.9f, 100.0f})
      for (int i = 1; i <= 200; ++i) {
        const float cosI = i / 200.0f;
        EXPECT_NEAR(fresnelConductor(cosI, Color3::Constant(eta), Color3::Constant(k)).x(),
                    reference(cosI, eta, k), 2e-4)
            << "eta " << eta << " k " << k << " cos " << cosI;
      }
}

TEST(Fresnel, SchlickEndpoints) {
  const Color3 f0(0.9f, 0.5f, 0.1f);
  EXPECT_TRUE(((fresnelSchlick(1.0f, f0) - f0).abs() < 1e-7f).all());
  EXPECT_TRUE(((fresnelSchlick(0.0f, f0) - 1.0f).abs() < 1e-7f).all());
}

TEST(Fresnel, RefractObeysSnell) {
  const Vector3f wi = direction(50);
  Vector3f wt;
  ASSERT_TRUE(refract(wi, Vector3f::UnitZ(), 1.5f, wt));
  EXPECT_NEAR(Vector3f(wi.x(), wi.y(), 0).norm(), 1.5f * Vector3f(wt.x(), wt.y(), 0).norm(), 1e-6f);
  EXPECT_LT(wt.z(), 0);
  EXPECT_NEAR(wt.norm(), 1.0f, 1e-6f);
  EXPECT_FALSE(refract(direction(60), Vector3f::UnitZ(), 1 / 1.5f, wt));  // TIR
}

}  // namespace
}  // namespace verity::test
