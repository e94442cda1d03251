// "Simulate only what the scene calls for": a scene that cannot carry light costs no ray.
#include <gtest/gtest.h>

#include "loader/scene_loader.h"
#include "render/renderer.h"

namespace verity {
namespace {

TEST(SimulateOnlyNeeded, NoEmitterAndBlackBackgroundTracesNoRay) {
  SceneFile file = loadSceneText(R"({
    "camera": {"resolution": [16, 16]},
    "integrator": {"type": "path_tracer_mis"},
    "background": 0,
    "surfaces": [{"type": "sphere", "transform": {"translate": [0, 0, -3]},
                  "material": {"type": "lambertian", "albedo": 0.5}}]})",
                                 "/tmp/dark.json");
  EXPECT_FALSE(file.scene->summary().hasEmitters());
  const auto integrator = makeIntegrator(file.integrator);
  Film film(file.scene->camera().resolution());
  RenderOptions options;
  options.samplesPerPixel = 4;
  const RenderStats stats = render(*file.scene, *integrator, *file.sampler, film, options);
  EXPECT_TRUE(stats.tracedNoRays);
  EXPECT_EQ(stats.rays, 0u);
  EXPECT_EQ(film.count(5, 5), 4u);
  EXPECT_TRUE(film.mean(5, 5).isZero());
}

TEST(SimulateOnlyNeeded, SummaryReportsWhatTheSceneUses) {
  SceneFile file = loadSceneText(R"({
    "camera": {},
    "background": {"type": "image", "filename": ")" VERITY_SOURCE_DIR
                                 R"(/scenes/textures/earth.png"},
    "surfaces": [
      {"type": "sphere", "material": {"type": "lambertian", "albedo": {"type": "checker"}}},
      {"type": "quad", "material": {"type": "lambertian", "albedo": 0.5}},
      {"type": "quad", "material": {"type": "diffuse light", "emit": 2}}]})",
                                 "/tmp/summary.json");
  const SceneSummary& s = file.scene->summary();
  EXPECT_TRUE(s.emittingBackground);
  EXPECT_EQ(s.areaLights, 1u);
  EXPECT_EQ(s.texturedMaterials, 1u);
  EXPECT_FALSE(s.hasDeltaLobes);
  EXPECT_TRUE(s.hasNonDeltaLobes);
  EXPECT_NE(s.explain().find("emitting background"), std::string::npos);
}

}  // namespace
}  // namespace verity
