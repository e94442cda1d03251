// Properties every material must have, checked over a list of configurations that covers
// the hard cases: roughness from 1e-4 to 1, incidence up to 89.99°, both sides of
// transmissive interfaces, relative indices 1 ± 1e-4, 2.4 and 1/2.4.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cctype>

#include "materials/tests/material_test_util.h"

namespace verity::test {
namespace {

struct Config {
  std::string json;
  bool twoSided = false;  // refracts, so wi may lie below the surface
  // Whether uniform sampling of the sphere estimates its integrals with a usable variance
  // (excludes delta lobes and very sharp lobes).
  bool crossCheck = false;
  double energyBound = 1.0;  // the model's analytic maximum albedo
};

// Names the configuration in test listings (GoogleTest would otherwise print its bytes).
void PrintTo(const Config& config, std::ostream* os) {
  *os << config.json;
}

std::vector<Config> configs() {
  std::vector<Config> c;
  c.push_back({R"({"type":"metal","albedo":[0.9,0.6,0.3],"roughness":0})"});
  c.push_back({R"({"type":"metal","albedo":1,"roughness":0.01})"});
  c.push_back({R"({"type":"metal","albedo":1,"roughness":0.6})", false, true});
  c.push_back({R"({"type":"metal","albedo":1,"roughness":0.6,"sampling":"normals"})", false, true});
  for (const char* ior : {"1.5", "2.4", "0.4166667", "1.0001", "0.9999"})
    c.push_back({fmt::format(R"({{"type":"dielectric","ior":{}}})", ior), true});
  for (const char* type : {"phong", "blinnphong"})
    for (const char* n : {"0", "1", "10", "1000"})
      c.push_back({fmt::format(R"({{"type":"{}","albedo":1,"exponent":{}}})", type, n), false,
                   std::string(n) != "1000"});
  for (const char* type : {"beckmann", "ggx"})
    for (const char* sampling : {"visible", "normals"})
      for (const char* alpha : {"0.0001", "0.01", "0.3", "1"})
        c.push_back(
            {fmt::format(
                 R"({{"type":"{}","albedo":1,"ab":{},"ior":0.05,"ext":3.9,"sampling":"{}"}})", type,
                 alpha, sampling),
             false, std::stod(alpha) >= 0.3});
  for (const char* dist : {"ggx", "beckmann"}) {
    for (const char* alpha : {"0.0001", "0.1", "1"})
      for (const char* ior : {"1.5", "2.4", "0.4166667", "1.0001"})
        c.push_back(
            {fmt::format(R"({{"type":"rough_dielectric","distribution":"{}","alpha":{},"ior":{}}})",
                         dist, alpha, ior),
             true, std::string(alpha) == "1" && std::string(ior) != "1.0001"});
    c.push_back(
        {fmt::format(
             R"({{"type":"rough_dielectric","distribution":"{}","alpha":0.5,"ior":1.5,"sampling":"normals"}})",
             dist),
         true, true});
  }
  c.push_back({R"({"type":"oren-nayar","albedo":1,"sigma":0})", false, true});
  c.push_back({R"({"type":"oren-nayar","albedo":1,"sigma":0.35})", false, true});
  c.push_back({R"({"type":"oren-nayar","albedo":1,"sigma":1.2})", false, true});
  {
    // σ below 0.326 rad: the model's grazing albedo A + B/2 exceeds 1 (see oren_nayar.h).
    const float s2 = 0.2f * 0.2f;
    const double a = 1 - s2 / (2 * (s2 + 0.33)), b = 0.45 * s2 / (s2 + 0.09);
    c.push_back({R"({"type":"oren-nayar","albedo":1,"sigma":0.2})", false, true, a + b / 2});
  }
  c.push_back(
      {R"({"type":"blend","a":{"type":"lambertian","albedo":1},"b":{"type":"metal","albedo":1,"roughness":0},"amount":0.3})"});
  c.push_back(
      {R"({"type":"blend","a":{"type":"ggx","albedo":1,"ab":0.4},"b":{"type":"phong","albedo":1},"amount":0.5})",
       false, true});
  c.push_back(
      {R"({"type":"blend","a":{"type":"dielectric","ior":1.5},"b":{"type":"rough_dielectric","alpha":0.3},"amount":0.6})",
       true});
  return c;
}

class MaterialProperties : public ::testing::TestWithParam<Config> {
 protected:
  void SetUp() override { material_ = makeMaterial(GetParam().json); }
  // Incident directions: the hard angles above the surface, and below it when two-sided.
  std::vector<Vector3f> incidentDirections() const {
    std::vector<Vector3f> dirs;
    for (double theta : incidenceAngles()) {
      dirs.push_back(direction(theta));
      if (GetParam().twoSided) dirs.push_back(direction(theta, 0.7, true));
    }
    return dirs;
  }
  std::shared_ptr<const Material> material_;
  TextureQuery q_;
};

// The JSON's letters and digits, so that a test's name says which material it checks.
std::string configName(const ::testing::TestParamInfo<Config>& info) {
  std::string name;
  for (char ch : info.param.json) {
    if (std::isalnum(static_cast<unsigned char>(ch)))
      name += ch;
    else if (ch == '.')
      name += 'p';
    else if (!name.empty() && name.back() != '_')
      name += '_';
  }
  while (!name.empty() && name.back() == '_') name.pop_back();
  return name;
}

bool finiteNonNegative(const Color3& c) {
  return c.allFinite() && (c >= 0).all();
}
bool finiteNonNegative(float v) {
  return std::isfinite(v) && v >= 0;
}

// eval and pdf never return NaN, Inf or negative values, including at the degenerate
// configurations wi = wo, wo = −wi, and directions in the tangent plane.
TEST_P(MaterialProperties, EvalAndPdfAreFiniteAndNonNegative) {
  Rng rng(1);
  std::vector<Vector3f> wis = incidentDirections();
  wis.push_back(Vector3f(1, 0, 0));
  wis.push_back(Vector3f(0.6f, 0.8f, 0));
  for (const Vector3f& wi : wis) {
    std::vector<Vector3f> wos = {wi,
                                 -wi,
                                 Vector3f(-wi.x(), -wi.y(), wi.z()),
                                 Vector3f(1, 0, 0),
                                 Vector3f(0, 0, 1),
                                 Vector3f(0, 0, -1)};
    for (int i = 0; i < 500; ++i) wos.push_back(warp::squareToUniformSphere(rng.next2()));
    for (const Vector3f& wo : wos) {
      for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
        const Color3 f = material_->eval(q_, wi, wo, mode);
        ASSERT_TRUE(finiteNonNegative(f)) << "wi " << wi.transpose() << " wo " << wo.transpose();
      }
      const float pdf = material_->pdf(q_, wi, wo);
      ASSERT_TRUE(finiteNonNegative(pdf)) << "wi " << wi.transpose() << " wo " << wo.transpose();
    }
  }
}

// A sample's weight is f·|cos θo|/pdf and its pdf is pdf(), both to 1e-4 relative; delta
// samples carry a finite non-negative throughput; lobes are among lobes() and lie on the
// side they claim. A tangent wi yields no sample or a valid one.
TEST_P(MaterialProperties, SamplesAgreeWithEvalAndPdf) {
  Rng rng(2);
  std::vector<Vector3f> wis = incidentDirections();
  wis.push_back(Vector3f(1, 0, 0));
  for (const Vector3f& wi : wis) {
    for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
      for (int i = 0; i < 2000; ++i) {
        const float uLobe = rng.next();
        const auto s = material_->sample(q_, wi, uLobe, rng.next2(), mode);
        if (!s) continue;
        ASSERT_TRUE(finiteNonNegative(s->weight)) << "wi " << wi.transpose();
        ASSERT_TRUE(s->wo.allFinite());
        ASSERT_NEAR(s->wo.norm(), 1.0f, 1e-4f);
        ASSERT_TRUE(std::isfinite(s->pdf) && s->pdf > 0);
        ASSERT_EQ(s->lobe & ~material_->lobes(), 0u);
        if (s->lobe & kTransmission) {
          ASSERT_LT(s->wo.z() * wi.z(), 0);
          ASSERT_GT(s->eta, 0);
        } else {
          ASSERT_GE(s->wo.z() * wi.z(), 0);
          ASSERT_EQ(s->eta, 1.0f);
        }
        if (s->isDelta()) continue;
        const float pdf = material_->pdf(q_, wi, s->wo);
        ASSERT_LE(relativeError(s->pdf, pdf), 1e-4f) << "wi " << wi.transpose();
        const Color3 expected = material_->eval(q_, wi, s->wo, mode) * std::abs(s->wo.z()) / pdf;
        for (int c = 0; c < 3; ++c)
          ASSERT_LE(relativeError(s->weight[c], expected[c], 1e-8f), 1e-4f)
              << "wi " << wi.transpose();
      }
    }
  }
}

// Reciprocity: f(wi, wo) = f(wo, wi) for reflection. Refraction, with η(w) the index of the
// medium w points into: f(wi, wo)/η(wi)² = f(wo, wi)/η(wo)² in radiance mode, and the
// importance-mode f(wi, wo) equals the radiance-mode f(wo, wi).
TEST_P(MaterialProperties, Reciprocity) {
  Rng rng(3);
  // The relative index of the interior for refractive materials (1 elsewhere).
  float ior = 1;
  const auto j = nlohmann::json::parse(GetParam().json);
  if (j.contains("ior") && GetParam().twoSided) ior = j["ior"].get<float>();
  if (j["type"] == "blend" && GetParam().twoSided) ior = 1.5f;  // both parts have ior 1.5
  int nonZero = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vector3f wi = warp::squareToUniformSphere(rng.next2());
    const Vector3f wo = warp::squareToUniformSphere(rng.next2());
    const Color3 fIO = material_->eval(q_, wi, wo, TransportMode::Radiance);
    const Color3 fOI = material_->eval(q_, wo, wi, TransportMode::Radiance);
    const Color3 fIOstar = material_->eval(q_, wi, wo, TransportMode::Importance);
    if (!isBlack(fIO)) ++nonZero;
    for (int c = 0; c < 3; ++c) {
      ASSERT_LE(relativeError(fIOstar[c], fOI[c]), 2e-4f)
          << wi.transpose() << " | " << wo.transpose();
      if (wi.z() * wo.z() > 0) {
        ASSERT_LE(relativeError(fIO[c], fOI[c]), 2e-4f)
            << wi.transpose() << " | " << wo.transpose();
      } else {
        const float etaI = wi.z() > 0 ? 1.0f : ior, etaO = wo.z() > 0 ? 1.0f : ior;
        ASSERT_LE(relativeError(fIO[c] / (etaI * etaI), fOI[c] / (etaO * etaO)), 2e-4f)
            << wi.transpose() << " | " << wo.transpose();
      }
    }
  }
  // (Sharp rough dielectrics are almost never non-zero at random pairs.)
  if (material_->hasNonDeltaLobe() && j["type"] != "rough_dielectric") {
    EXPECT_GT(nonZero, 0);
  }
}

// Energy: the albedo ∫ f |cos θo| dωo, estimated by the mean sample weight in importance
// mode (radiance mode legitimately exceeds 1 across refraction by η²), must not exceed the
// model's bound (1, or Oren-Nayar's analytic grazing maximum) by more than kSigmas
// standard errors of the estimate.
TEST_P(MaterialProperties, EnergyConservation) {
  Rng rng(4);
  const int n = 20000;
  for (const Vector3f& wi : incidentDirections()) {
    MeanEstimate albedo[3];
    for (int i = 0; i < n; ++i) {
      const auto s = material_->sample(q_, wi, rng.next(), rng.next2(), TransportMode::Importance);
      for (int c = 0; c < 3; ++c) albedo[c].add(s ? s->weight[c] : 0.0);
    }
    for (int c = 0; c < 3; ++c) {
      EXPECT_LE(albedo[c].mean(),
                GetParam().energyBound + kSigmas * albedo[c].standardError() + 1e-6)
          << "wi " << wi.transpose() << " channel " << c << " se " << albedo[c].standardError();
    }
  }
}

// The sampler draws from the density pdf() describes: two independent estimates must
// agree within kSigmas combined standard errors, for incidences up to 85°:
//  - the albedo by BSDF sampling (mean weight) and by uniform sampling of the sphere;
//  - the fraction of valid samples and ∫ pdf dω over the sphere (uniform sampling): with
//    invalid samples given weight zero, the pdf integrates to exactly that fraction.
// Registered only for the configurations where uniform sampling has a usable variance.
class MaterialCrossCheck : public MaterialProperties {};

std::vector<Config> crossCheckConfigs() {
  std::vector<Config> c;
  for (const Config& config : configs())
    if (config.crossCheck) c.push_back(config);
  return c;
}

TEST_P(MaterialCrossCheck, SamplerMatchesPdfAndEval) {
  Rng rng(5);
  const int n = 100000;
  for (double theta : {0.0, 40.0, 70.0, 85.0}) {
    for (bool below : {false, true}) {
      if (below && !GetParam().twoSided) continue;
      const Vector3f wi = direction(theta, 0.7, below);
      MeanEstimate byBsdf, valid, byUniform, pdfIntegral;
      for (int i = 0; i < n; ++i) {
        const auto s = material_->sample(q_, wi, rng.next(), rng.next2(), TransportMode::Radiance);
        byBsdf.add(s ? s->weight.mean() : 0.0);
        valid.add(s ? 1.0 : 0.0);
        const Vector3f wo = warp::squareToUniformSphere(rng.next2());
        const double invP = 4.0 * 3.14159265358979323846;
        byUniform.add(material_->eval(q_, wi, wo, TransportMode::Radiance).mean() *
                      std::abs(wo.z()) * invP);
        pdfIntegral.add(material_->pdf(q_, wi, wo) * invP);
      }
      const double seA = std::hypot(byBsdf.standardError(), byUniform.standardError());
      EXPECT_LE(std::abs(byBsdf.mean() - byUniform.mean()), kSigmas * seA + 1e-6)
          << "theta " << theta << (below ? " below" : "") << ": sampled " << byBsdf.mean()
          << ", uniform " << byUniform.mean();
      const double seP = std::hypot(valid.standardError(), pdfIntegral.standardError());
      EXPECT_LE(std::abs(valid.mean() - pdfIntegral.mean()), kSigmas * seP + 1e-6)
          << "theta " << theta << (below ? " below" : "") << ": valid " << valid.mean()
          << ", integral of pdf " << pdfIntegral.mean();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Materials, MaterialProperties, ::testing::ValuesIn(configs()), configName);
INSTANTIATE_TEST_SUITE_P(Materials, MaterialCrossCheck, ::testing::ValuesIn(crossCheckConfigs()),
                         configName);

}  // namespace
}  // namespace verity::test
