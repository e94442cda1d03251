// The light tracer sees an emitting background directly: light subpaths
// that start on the environment are connected to the lens along their own direction. It must
// match path_tracer_mats, which finds the background only by escaping rays and traces no
// shadow ray, region by region: on scenes/analytic-sphere.json (a constant background, the
// only emitter), and on a scene lit by an image background and a small area light together
// (the environment is chosen with probability below one, and its directions by the image's
// luminance), seen through a pinhole and through a thin lens (the lens point is sampled for
// a direction, not for a point).
//
// Regions are 4×4 blocks of the image; estimates are per-pass block sums over independent
// passes (bdpt_test_util.h); two-sided z-tests at family-wise level 1% with a Bonferroni
// correction over every comparison in this file. Power: every block that sees background
// must be non-zero in the light tracer's image, so a black background fails.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "integrators/tests/bdpt_test_util.h"

namespace verity::light_tracer_background_test {
namespace {

using bdpt_test::estimateRegions;

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string environmentScene(const std::string& camera) {
  return R"({
  "camera": {"transform": {"from": [0, 1.2, 4], "at": [0, 0.2, 0], "up": [0, 1, 0]}, )" +
         camera + R"(},
  "sampler": {"type": "independent"},
  "background": {"type": "image", "filename": ")" VERITY_SOURCE_DIR R"(/scenes/textures/earth.png"},
  "materials": [
    {"name": "floor", "type": "lambertian", "albedo": [0.5, 0.6, 0.7]},
    {"name": "ball", "type": "oren_nayar", "albedo": 0.7, "sigma": 0.35},
    {"name": "light", "type": "diffuse light", "emit": 4}
  ],
  "surfaces": [
    {"type": "quad", "size": 3, "material": "floor",
     "transform": [{"axis": [1, 0, 0], "angle": -90}, {"translate": [0, -0.5, 0]}]},
    {"type": "sphere", "radius": 0.6, "material": "ball", "transform": {"translate": [0, 0.2, 0]}},
    {"type": "quad", "size": 0.5, "material": "light",
     "transform": [{"axis": [1, 0, 0], "angle": 90}, {"translate": [0.8, 1.5, 0.5]}]}
  ]
})";
}

struct BackgroundCase {
  const char* name;
  std::string scene;
};

void PrintTo(const BackgroundCase& c, std::ostream* os) {
  *os << c.name;
}

constexpr int kBlocks = 4;
constexpr int kCases = 3;
constexpr int kTests = kBlocks * kBlocks * 3 * kCases;
// Seeds of the passes, one base per integrator, fixed once.
constexpr uint64_t kMaterialsSeeds = 4100;
constexpr uint64_t kLightTracerSeeds = 4600;

class LightTracerBackground : public ::testing::TestWithParam<BackgroundCase> {};

TEST_P(LightTracerBackground, MatchesMaterialSamplingPerRegion) {
  const BackgroundCase& c = GetParam();
  const SceneFile file = loadSceneText(c.scene, "/tmp/light-tracer-background.json");
  const Vector2i res = file.scene->camera().resolution();
  const auto block = [&](int x, int y) {
    return (y * kBlocks / res.y()) * kBlocks + x * kBlocks / res.x();
  };
  const int regions = kBlocks * kBlocks;
  // Which blocks see the background through some pixel centre.
  std::vector<bool> seesBackground(regions, false);
  for (int y = 0; y < res.y(); ++y)
    for (int x = 0; x < res.x(); ++x) {
      SurfaceInteraction si;
      const Ray ray =
          file.scene->camera().generateRay(Point2f(x + 0.5f, y + 0.5f), Point2f(0.5f, 0.5f));
      if (!file.scene->intersect(ray, si)) seesBackground[block(x, y)] = true;
    }
  const auto reference =
      estimateRegions(c.scene, "path_tracer_mats", 3, 200, kMaterialsSeeds, regions, block);
  const auto light =
      estimateRegions(c.scene, "light_tracer", 3, 300, kLightTracerSeeds, regions, block);
  const double z = bdpt_test::bonferroniZ(0.01, kTests);
  int backgroundBlocks = 0;
  for (int r = 0; r < regions; ++r) {
    const std::string where = std::string(c.name) + ", block " + std::to_string(r);
    bdpt_test::expectSameMean(light[r], reference[r], z, where);
    EXPECT_EQ(light[r].invalidSamples, 0u) << where;
    if (seesBackground[r]) {
      ++backgroundBlocks;
      EXPECT_GT(light[r].mean.sum(), 0) << where << " sees the background";
    }
  }
  EXPECT_GE(backgroundBlocks, 4) << "the scene must show its background";
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, LightTracerBackground,
    ::testing::Values(
        BackgroundCase{"AnalyticSphere",
                       readFile(VERITY_SOURCE_DIR "/scenes/analytic-sphere.json")},
        BackgroundCase{"ImageBackgroundPinhole",
                       environmentScene(R"("vfov": 50, "resolution": [24, 20])")},
        BackgroundCase{"ImageBackgroundThinLens",
                       environmentScene(
                           R"("vfov": 50, "resolution": [24, 20], "aperture": 0.2, "fdist": 4)")}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace verity::light_tracer_background_test
