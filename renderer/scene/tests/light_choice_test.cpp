// Next-event estimation's choice of a light at a point: proportional to each light's
// contribution estimate there (radiance times the solid angle it subtends), none for a light
// that faces away, by power with one light or very many; the density it reports is the one it
// samples with.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "loader/scene_loader.h"
#include "scene/scene.h"
#include "shapes/sphere.h"

namespace verity {
namespace {

constexpr const char* kCamera = R"("camera": {"resolution": [4, 4]})";

SceneFile sceneOf(const std::string& surfaces) {
  return loadSceneText(fmt::format("{{{}, \"surfaces\": [{}]}}", kCamera, surfaces),
                       "/tmp/light_choice.json");
}

// A quad of `size` and radiance `emit` centred on the z axis at `z`, facing +z.
std::string quad(float size, float emit, float z) {
  return fmt::format(
      R"({{"type": "quad", "size": {}, "material": {{"type": "diffuse light", "emit": {}}},
          "transform": {{"translate": [0, 0, {}]}}}})",
      size, emit, z);
}

// From the origin: a 1 × 1 quad of radiance 4 at distance 1 below (1 sr by the small-light
// estimate, weight 4), a 2 × 2 quad of radiance 1 at distance 4 below (0.25 sr, weight 0.25),
// and a bright quad above that faces away (weight 0).
TEST(LightChoice, ProportionalToTheContributionEstimate) {
  const SceneFile f = sceneOf(quad(1, 4, -1) + ", " + quad(2, 1, -4) + ", " + quad(1, 100, 1));
  const Scene& scene = *f.scene;
  const LightChoice choice = scene.lightChoice(Point3f::Zero());
  const auto& lights = scene.lights();
  ASSERT_EQ(lights.size(), 3u);
  const double expected[] = {4 / 4.25, 0.25 / 4.25, 0};
  for (size_t i = 0; i < 3; ++i)
    EXPECT_NEAR(choice.pmf(lights[i]), expected[i], 1e-6) << "light " << i;
  // Stratified choices: each light's share within one stratum of its probability, and the
  // probability each choice reports is pmf()'s.
  constexpr int kChoices = 100000;
  int counts[3] = {0, 0, 0};
  for (int k = 0; k < kChoices; ++k) {
    float pmf = 0;
    const Light* light = choice.sample((k + 0.5f) / kChoices, &pmf);
    ASSERT_NE(light, nullptr);
    ASSERT_EQ(pmf, choice.pmf(light));
    ++counts[light->index];
  }
  for (size_t i = 0; i < 3; ++i)
    EXPECT_NEAR(double(counts[i]) / kChoices, expected[i], 2.0 / kChoices) << "light " << i;
  EXPECT_EQ(counts[2], 0);
}

// Where no light faces the point, none is chosen: every light would be sampled in vain.
TEST(LightChoice, NoneWhereEveryLightFacesAway) {
  const SceneFile f = sceneOf(quad(1, 1, 1) + ", " + quad(1, 1, 2));
  const LightChoice choice = f.scene->lightChoice(Point3f::Zero());
  float pmf = 1;
  EXPECT_EQ(choice.sample(0.3f, &pmf), nullptr);
  EXPECT_EQ(pmf, 0);
  EXPECT_EQ(choice.pmf(f.scene->lights()[0]), 0);
}

// One light is chosen always, even from behind it (a point sees nothing of it there, and
// sampleLi declines); more lights than LightChoice::kMaxLightsByContribution are chosen by
// power.
TEST(LightChoice, ByPowerWithOneLightOrVeryMany) {
  const SceneFile one = sceneOf(quad(1, 1, 1));
  float pmf = 0;
  EXPECT_EQ(one.scene->lightChoice(Point3f::Zero()).sample(0.5f, &pmf), one.scene->lights()[0]);
  EXPECT_EQ(pmf, 1);
  std::string many;
  for (size_t i = 0; i <= LightChoice::kMaxLightsByContribution; ++i)
    many += (i ? ", " : "") + quad(1, float(i + 1), -1.0f - float(i));
  const SceneFile f = sceneOf(many);
  ASSERT_GT(f.scene->lights().size(), LightChoice::kMaxLightsByContribution);
  const LightChoice choice = f.scene->lightChoice(Point3f::Zero());
  for (const Light* light : f.scene->lights())
    EXPECT_EQ(choice.pmf(light), f.scene->lightPmf(light));
}

// A sphere's estimate is its visible cone's solid angle, 2π(1 − cos θmax): for a unit sphere
// seen from distance 2, θmax = 30°.
TEST(LightChoice, ASpheresEstimateIsItsVisibleCone) {
  const SceneFile f = sceneOf(
      R"({"type": "sphere", "radius": 1, "material": {"type": "diffuse light", "emit": 1}})");
  const Shape& sphere = f.scene->shapes().front().operator*();
  ASSERT_NE(dynamic_cast<const Sphere*>(&sphere), nullptr);
  EXPECT_NEAR(sphere.solidAngleEstimate(Point3f(0, 0, 2)), 2 * kPi * (1 - std::sqrt(3.0) / 2),
              1e-6);
  EXPECT_EQ(sphere.solidAngleEstimate(Point3f(0, 0, 0.5f)), 2 * double{kPi});  // inside
}

}  // namespace
}  // namespace verity
