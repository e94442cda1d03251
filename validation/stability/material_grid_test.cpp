// Every material, evaluated and sampled over a dense grid of hard parameters: roughness α
// from 1e-4 to 1, incidence up to 89.99° from both sides, wo = ±wi, relative indices from
// 1.0001 to 4 and their inverses. Nothing may be NaN, Inf or negative, and the visible-normal
// weight of a rough conductor may not exceed its Fresnel term. Materials see only local
// directions; shading normals tilted against the geometric normal are the renderer's concern
// and are stressed in scenes/stress/tilted-normals.json (stress_scenes_test.cpp).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "materials/fresnel.h"
#include "materials/material_registry.h"
#include "materials/named_conductors.h"
#include "materials/tests/material_test_util.h"

namespace verity::test {
namespace {

// A conductor whose visible-normal sample weight is bounded by its Fresnel term.
struct FresnelBound {
  bool schlick = false;
  Color3 f0 = Color3::Ones();  // Schlick's reflectance at normal incidence (× tint)
  Color3 eta = Color3::Zero(), k = Color3::Zero();
};

struct GridMaterial {
  GridMaterial(std::string j, std::optional<FresnelBound> b = std::nullopt)
      : json(std::move(j)), bound(b) {}
  std::string json;
  std::optional<FresnelBound> bound;
};

const std::vector<double> kAlphas = {1e-4, 1e-3, 0.01, 0.1, 0.5, 1};
const std::vector<double> kThetas = {0, 30, 60, 85, 89, 89.9, 89.99};

std::vector<double> relativeIors() {
  std::vector<double> iors;
  for (double ior : {1.0001, 1.001, 1.33, 1.5, 2.4, 4.0}) {
    iors.push_back(ior);
    iors.push_back(1 / ior);
  }
  return iors;
}

std::vector<GridMaterial> gridMaterials() {
  std::vector<GridMaterial> m;
  m.push_back({R"({"type":"lambertian","albedo":[0.9,0.5,0.1]})"});
  m.push_back({R"({"type":"diffuse_light","emit":[1,2,3]})"});
  m.push_back({R"({"type":"metal","albedo":[0.9,0.6,0.3],"roughness":0})"});
  for (double ior : relativeIors())
    m.push_back({fmt::format(R"({{"type":"dielectric","ior":{}}})", ior)});
  for (double alpha : kAlphas) {
    // Blinn-Phong's exponent for a Beckmann-like width α is 2/α² − 2 (Walter et al. 2007,
    // eq. 30), capped at the scene format's limit of 1e6.
    const double exponent = std::min(2 / (alpha * alpha) - 2, 1e6);
    for (const char* type : {"phong", "blinnphong"})
      m.push_back(
          {fmt::format(R"({{"type":"{}","albedo":[0.9,0.5,0.1],"exponent":{}}})", type, exponent)});
    for (const char* sampling : {"visible", "normals"}) {
      const bool visible = std::string(sampling) == "visible";
      for (const char* type : {"beckmann", "ggx"}) {
        for (auto [eta, k] : {std::pair{0.05, 3.9}, std::pair{1.5, 0.0}, std::pair{0.2, 0.5}}) {
          FresnelBound b;
          b.f0 = Color3(0.9f, 0.6f, 0.3f);
          b.eta = Color3::Constant(float(eta));
          b.k = Color3::Constant(float(k));
          m.push_back(
              {fmt::format(
                   R"({{"type":"{}","albedo":[0.9,0.6,0.3],"ab":{},"ior":{},"ext":{},"sampling":"{}"}})",
                   type, alpha, eta, k, sampling),
               visible ? std::optional(b) : std::nullopt});
        }
        // One index per channel: an RGB triple spanning the three pairs above, and the
        // measured metals.
        FresnelBound rgb;
        rgb.f0 = Color3(0.9f, 0.6f, 0.3f);
        rgb.eta = Color3(0.05f, 1.5f, 0.2f);
        rgb.k = Color3(3.9f, 0.0f, 0.5f);
        m.push_back(
            {fmt::format(
                 R"({{"type":"{}","albedo":[0.9,0.6,0.3],"ab":{},"ior":[0.05,1.5,0.2],"ext":[3.9,0,0.5],"sampling":"{}"}})",
                 type, alpha, sampling),
             visible ? std::optional(rgb) : std::nullopt});
        for (const NamedConductor& c : namedConductors()) {
          FresnelBound b;
          b.f0 = Color3::Constant(0.8f);  // the default albedo, a tint
          b.eta = c.eta;
          b.k = c.k;
          m.push_back({fmt::format(R"({{"type":"{}","ab":{},"conductor":"{}","sampling":"{}"}})",
                                   type, alpha, c.name, sampling),
                       visible ? std::optional(b) : std::nullopt});
        }
      }
      // DIRT's rough metal: GGX with α = roughness², Schlick's Fresnel with F0 = albedo.
      FresnelBound schlick;
      schlick.schlick = true;
      schlick.f0 = Color3(0.9f, 0.6f, 0.3f);
      m.push_back(
          {fmt::format(
               R"({{"type":"metal","albedo":[0.9,0.6,0.3],"roughness":{},"sampling":"{}"}})",
               std::sqrt(alpha), sampling),
           visible ? std::optional(schlick) : std::nullopt});
      for (const char* dist : {"ggx", "beckmann"})
        for (double ior : relativeIors())
          m.push_back({fmt::format(
              R"({{"type":"rough_dielectric","distribution":"{}","alpha":{},"ior":{},"sampling":"{}"}})",
              dist, alpha, ior, sampling)});
    }
  }
  for (double sigma : {0.0, 0.1, 0.35, 1.0, 1.57})
    m.push_back(
        {fmt::format(R"({{"type":"oren-nayar","albedo":[0.9,0.5,0.1],"sigma":{}}})", sigma)});
  for (double amount : {0.0, 0.3, 1.0}) {
    m.push_back({fmt::format(
        R"({{"type":"blend","a":{{"type":"lambertian","albedo":1}},"b":{{"type":"metal","albedo":1,"roughness":0}},"amount":{}}})",
        amount)});
    m.push_back({fmt::format(
        R"({{"type":"blend","a":{{"type":"dielectric","ior":1.5}},"b":{{"type":"rough_dielectric","alpha":0.001,"ior":0.5}},"amount":{}}})",
        amount)});
    m.push_back({fmt::format(
        R"({{"type":"blend","a":{{"type":"ggx","ab":0.0001}},"b":{{"type":"oren-nayar","sigma":1}},"amount":{}}})",
        amount)});
  }
  return m;
}

bool finiteNonNegative(const Color3& c) {
  return c.allFinite() && (c >= 0).all();
}
bool finiteNonNegative(float v) {
  return std::isfinite(v) && v >= 0;
}

// Incident directions on both sides at every grid angle (for one-sided materials the lower
// side must give zeros or no sample, never garbage), and the tangent direction itself.
std::vector<Vector3f> incidentDirections() {
  std::vector<Vector3f> dirs;
  for (double theta : kThetas)
    for (bool below : {false, true}) dirs.push_back(direction(theta, 0.7, below));
  dirs.push_back(Vector3f(1, 0, 0));
  return dirs;
}

// Random numbers for sample(): a jittered grid plus the corners of [0, 1)², where inverse
// CDFs reach their singularities.
std::vector<Point2f> sampleGrid() {
  std::vector<Point2f> u;
  const float kOneMinus = 0x1.fffffep-1f;
  for (float a : {0.0f, kOneMinus})
    for (float b : {0.0f, kOneMinus}) u.emplace_back(a, b);
  Rng rng(11);
  constexpr int kSide = 6;
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j)
      u.emplace_back((float(i) + rng.next()) / kSide, (float(j) + rng.next()) / kSide);
  return u;
}

// Relative slack of the Fresnel bound: the weight F·G2/G1 and F are computed in float in a
// different order, so they may differ by a few ulp (1e-7 each); a wrong G1 or F would exceed
// the bound by far more.
constexpr float kBoundTolerance = 1e-4f;

TEST(MaterialGrid, NoNanInfOrNegativeAndVisibleNormalWeightsBoundedByFresnel) {
  const std::vector<GridMaterial> materials = gridMaterials();
  const std::vector<Vector3f> wis = incidentDirections();
  const std::vector<Point2f> us = sampleGrid();
  const TextureQuery q;
  Rng rng(7);
  long evaluations = 0, boundChecks = 0;
  for (const GridMaterial& gm : materials) {
    SCOPED_TRACE(gm.json);
    const auto material = makeMaterial(gm.json);
    for (const Vector3f& wi : wis) {
      std::vector<Vector3f> wos = {wi,
                                   -wi,
                                   Vector3f(-wi.x(), -wi.y(), wi.z()),
                                   Vector3f(wi.x(), wi.y(), -wi.z()),
                                   Vector3f(0, 0, 1),
                                   Vector3f(0, 0, -1)};
      for (int i = 0; i < 24; ++i) wos.push_back(warp::squareToUniformSphere(rng.next2()));
      for (const Vector3f& wo : wos) {
        for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
          const Color3 f = material->eval(q, wi, wo, mode);
          ASSERT_TRUE(finiteNonNegative(f))
              << "eval wi " << wi.transpose() << " wo " << wo.transpose() << " f " << f.transpose();
        }
        const float pdf = material->pdf(q, wi, wo);
        ASSERT_TRUE(finiteNonNegative(pdf))
            << "pdf wi " << wi.transpose() << " wo " << wo.transpose() << " pdf " << pdf;
        evaluations += 3;
      }
      for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
        for (size_t i = 0; i < us.size(); ++i) {
          for (float uLobe : {0.0f, 0.5f, 0x1.fffffep-1f}) {
            const auto s = material->sample(q, wi, uLobe, us[i], mode);
            ++evaluations;
            if (!s) continue;
            ASSERT_TRUE(finiteNonNegative(s->weight) && finiteNonNegative(s->pdf) &&
                        s->wo.allFinite())
                << "sample wi " << wi.transpose() << " u " << us[i].transpose() << " weight "
                << s->weight.transpose() << " pdf " << s->pdf << " wo " << s->wo.transpose();
            if (!gm.bound || wi.z() <= 0 || s->wo.z() <= 0) continue;
            // Visible-normal sampling: weight = tint·F(wi·h)·G2/G1(wi) (Heitz 2018, "Sampling
            // the GGX Distribution of Visible Normals", JCGT 7(4)), and the height-correlated
            // G2 never exceeds G1(wi) (Heitz 2014, "Understanding the Masking-Shadowing
            // Function in Microfacet-Based BRDFs"), so weight ≤ tint·F.
            const Vector3f h = (wi + s->wo).normalized();
            const float cosH = wi.dot(h);
            const Color3 f =
                gm.bound->schlick
                    ? fresnelSchlick(cosH, gm.bound->f0)
                    : Color3(gm.bound->f0 * fresnelConductor(cosH, gm.bound->eta, gm.bound->k));
            for (int c = 0; c < 3; ++c)
              ASSERT_LE(s->weight[c], f[c] * (1 + kBoundTolerance))
                  << "channel " << c << " wi " << wi.transpose() << " wo " << s->wo.transpose();
            ++boundChecks;
          }
        }
      }
    }
  }
  // The grid must reach every case it claims to (a grid that samples nothing tests nothing).
  EXPECT_GT(boundChecks, 1000);
  std::printf(
      "material grid: %zu materials, %ld evaluations (eval, pdf, sample), %ld Fresnel "
      "bound checks\n",
      materials.size(), evaluations, boundChecks);
  ::testing::Test::RecordProperty("materials", int(materials.size()));
  ::testing::Test::RecordProperty("evaluations", std::to_string(evaluations));
  ::testing::Test::RecordProperty("fresnel_bound_checks", std::to_string(boundChecks));
}

// Types the grid leaves out, with the reason: none so far. A material type added to the
// scene format without an entry in gridMaterials() fails below.
const std::map<std::string, std::string> kNotInGrid = {};

TEST(MaterialGrid, EveryMaterialTypeIsInTheGrid) {
  std::set<std::string> inGrid;
  for (const GridMaterial& gm : gridMaterials()) {
    const std::string spelling = JsonNode::parse(gm.json, "grid").type();
    const MaterialType* t = findMaterialType(spelling);
    ASSERT_NE(t, nullptr) << gm.json;
    inGrid.insert(t->name);
  }
  for (const MaterialType& t : materialTypes())
    EXPECT_TRUE(inGrid.count(t.name) || kNotInGrid.count(t.name))
        << "material type \"" << t.name << "\" has no entry in gridMaterials()";
}

}  // namespace
}  // namespace verity::test
