// Rigid-motion invariance: every shipped, stress and cross-check scene, moved as a whole
// with its camera (rigid_motion.h: onto the coordinate planes, far away, turned by 90° steps and by
// 37°, mirrored), must render the same image with every integrator. Nothing here compares
// two integrators, so a defect they all share (one tied to a coordinate plane, say) still shows.
//
//   - Per 16×16 tile and channel, a Welch t-test of the moved image's mean against the
//     original's, from batch means (batch_regions.h: splats correlate the pixels of a pass);
//     the mirror image is compared tile by mirrored tile. One Holm family over every test of
//     every scene, integrator and motion: family-wise level 1%.
//   - Each integrator renders a scene, original and moved, with the sampler that its place
//     takes in turn (suite_samplers.h: independent, halton, sobol along the scenes and the
//     integrators).
//   - Power: cornell-box moved onto the coordinate planes and rendered with more samples by
//     path_tracer_nee must be found different when made 1% brighter, and agree when not.
// Seeds are fixed by the names of the scene, integrator and motion (hashString), never tuned.
#include "validation/invariance/rigid_motion.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>

#include "integrators/integrator_registry.h"
#include "integrators/integrator_settings.h"
#include "render/render_batches.h"
#include "render/renderer.h"
#include "validation/compare/batch_regions.h"
#include "validation/compare/comparison_family.h"
#include "validation/compare/suite_samplers.h"
#include "validation/studies/study_scene.h"

namespace verity::validation {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(VERITY_SOURCE_DIR) / "scenes";

constexpr int kWidth = 32;
constexpr int kTileSize = 16;
constexpr int kMaxBounces = 5;
constexpr int kBatches = 16;
constexpr int kBatchSpp = 4;
constexpr double kFamilyWiseLevel = 0.01;

// `batches` independent renders of `spp` samples per pixel, as region means.
BatchRegions renderBatches(const SceneFile& file, const std::string& integrator,
                           const std::vector<int>& regionOf, int regions, int batches, int spp,
                           const std::string& key) {
  BatchRegions out(regionOf, regions, key);
  verity::renderBatches(file, integrator, kMaxBounces, batches, spp, key,
                        [&](const Film& film) { out.addBatch(film); });
  return out;
}

// The tile regions of an image mirrored left to right: pixel (x, y) belongs to the tile of
// (w − 1 − x, y), so that region r of a mirrored render compares with region r of the
// original.
std::vector<int> mirroredRegions(const std::vector<int>& regionOf, int width) {
  std::vector<int> mirrored(regionOf.size());
  for (size_t i = 0; i < regionOf.size(); ++i) {
    const size_t x = i % width, row = i - x;
    mirrored[i] = regionOf[row + (width - 1 - x)];
  }
  return mirrored;
}

struct Scene {
  nlohmann::json json;  // as the file has it
  std::filesystem::path file;
  int width = 0;  // the image width it is loaded at
  SceneFile loaded;
  int tiles = 0;
  std::vector<int> regionOf, mirroredRegionOf;
};

Scene prepare(const std::filesystem::path& file, int width) {
  Scene s;
  s.file = file;
  s.width = width;
  s.json = nlohmann::json::parse(std::ifstream(file));
  s.loaded = loadSceneText(s.json.dump(), file, SceneOverrides::atWidth(width));
  const Vector2i res = s.loaded.scene->camera().resolution();
  s.regionOf = tileRegions(res.x(), res.y(), kTileSize, &s.tiles);
  s.mirroredRegionOf = mirroredRegions(s.regionOf, res.x());
  return s;
}

// The scene moved, rendered with the original's sampler, against the original's batches.
BatchRegions renderMoved(const Scene& s, const RigidMotion& motion, const std::string& integrator,
                         int batches, int spp, const std::string& key) {
  SceneFile moved =
      loadSceneText(moveScene(s.json, motion).dump(), s.file, SceneOverrides::atWidth(s.width));
  moved.sampler = s.loaded.sampler->clone();
  return renderBatches(moved, integrator, motion.mirrors ? s.mirroredRegionOf : s.regionOf, s.tiles,
                       batches, spp, key);
}

TEST(RigidMotion, ImagesDoNotChange) {
  const auto start = std::chrono::steady_clock::now();
  ComparisonFamily family(kFamilyWiseLevel);
  int renders = 0;
  const std::vector<std::filesystem::path> files = studies::shippedScenes(kScenes);
  for (size_t f = 0; f < files.size(); ++f) {
    const std::filesystem::path& file = files[f];
    Scene s = prepare(file, kWidth);
    const std::string name = studies::shippedSceneName(file);
    const std::vector<RigidMotion> motions = standardMotions(*s.loaded.scene);
    std::string names;
    for (const RigidMotion& motion : motions) names += " " + motion.name;
    fmt::print("{}:{}\n", name, names);
    const std::vector<std::string> integrators = radianceIntegrators();
    for (size_t i = 0; i < integrators.size(); ++i) {
      const std::string& integrator = integrators[i];
      const char* sampler = suiteSampler(int(f), int(i));
      useSampler(s.loaded, sampler, kBatchSpp);
      const std::string key = fmt::format("{} {} {}", name, integrator, sampler);
      const BatchRegions original = renderBatches(s.loaded, integrator, s.regionOf, s.tiles,
                                                  kBatches, kBatchSpp, key + " original");
      const PixelStatistics reference = original.statistics();
      for (const RigidMotion& motion : motions) {
        const BatchRegions moved =
            renderMoved(s, motion, integrator, kBatches, kBatchSpp, key + " " + motion.name);
        family.add(key + " " + motion.name, reference, moved.statistics());
        renders += 2;
      }
    }
  }
  fmt::print("{} renders of {} batches of {} spp at {} pixels wide in {:.1f} s\n", renders,
             kBatches, kBatchSpp, kWidth,
             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  EXPECT_EQ(family.decide("rigid motions, all scenes").rejections, 0);
}

// The power check: with enough samples the comparison finds a 1% brightness change. The
// family holds one comparison, decided at 1% like the suite's.
TEST(RigidMotion, FindsAOnePercentChange) {
  const Scene s = prepare(kScenes / "cornell-box.json", kWidth);
  const RigidMotion planes = standardMotions(*s.loaded.scene).front();
  ASSERT_EQ(planes.name, "planes");
  constexpr int kPowerSpp = 128;
  const PixelStatistics original = renderBatches(s.loaded, "path_tracer_nee", s.regionOf, s.tiles,
                                                 kBatches, kPowerSpp, "power original")
                                       .statistics();
  const PixelStatistics moved =
      renderMoved(s, planes, "path_tracer_nee", kBatches, kPowerSpp, "power planes").statistics();
  ComparisonFamily same(kFamilyWiseLevel), brighter(kFamilyWiseLevel);
  same.add("cornell-box planes", original, moved);
  brighter.add("cornell-box planes, 1% brighter", original, scaledStatistics(moved, 1.01));
  EXPECT_EQ(same.decide("cornell-box on the coordinate planes").rejections, 0);
  const ComparisonFamily::Decision decision = brighter.decide("the same, 1% brighter");
  ASSERT_LT(decision.detectableBias, 0.01);
  EXPECT_GT(decision.rejections, 0);
}

}  // namespace
}  // namespace verity::validation
