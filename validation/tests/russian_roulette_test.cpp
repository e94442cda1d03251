// Russian roulette ("rr_depth", "rr_threshold") changes the images of every integrator that
// walks paths, but not what they estimate: renders without roulette, with the default roulette
// and with the most aggressive one the keys allow short of their floor (from the first bounce,
// threshold 1) agree by per-tile Welch t-tests.
//
//   - cornell-box at 32 pixels wide, max_bounces 5 (paths of up to 5 bounces, so roulette
//     decides at 1 to 5 bounces with rr_depth 1; rr_depth 6 is no roulette);
//   - per 16×16 tile and channel, batch means of 16 independent renders of 4 spp per side
//     (batch_regions.h: splats correlate a pass's pixels);
//   - one Holm family over every test of the path tracers, BDPT and the light tracer:
//     family-wise level 1%.
// Seeds are fixed by the integrator's name (hashString), the same on both sides, so that the
// images differ only by the roulette.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "loader/scene_loader.h"
#include "tile_batches.h"
#include "validation/compare/comparison_family.h"

namespace verity::validation {
namespace {

constexpr int kWidth = 32;
constexpr int kTileSize = 16;
constexpr int kMaxBounces = 5;
constexpr int kBatches = 16;
constexpr int kBatchSpp = 4;
constexpr double kFamilyWiseLevel = 0.01;

PixelStatistics renderTiles(const SceneFile& file, const std::string& integrator,
                            const std::string& key) {
  return testing::renderTileBatches(file, integrator, kMaxBounces, kBatches, kBatchSpp, kTileSize,
                                    key);
}

TEST(RussianRoulette, ChangesImagesNotTheirExpectation) {
  const std::filesystem::path scene =
      std::filesystem::path(VERITY_SOURCE_DIR) / "scenes" / "cornell-box.json";
  SceneFile none = loadScene(scene, SceneOverrides::atWidth(kWidth));
  SceneFile atDefault = loadScene(scene, SceneOverrides::atWidth(kWidth));
  SceneFile aggressive = loadScene(scene, SceneOverrides::atWidth(kWidth));
  ASSERT_EQ(atDefault.integrator.rrDepth, kDefaultRouletteDepth);
  ASSERT_FALSE(atDefault.integrator.rrThreshold.has_value());  // each type's own
  none.integrator.rrDepth = kMaxBounces + 1;
  aggressive.integrator.rrDepth = 1;
  aggressive.integrator.rrThreshold = 1;
  ComparisonFamily family(kFamilyWiseLevel);
  for (const char* integrator :
       {"path_tracer_mats", "path_tracer_nee", "path_tracer_mis", "bdpt", "light_tracer"}) {
    const std::string key = fmt::format("roulette {}", integrator);
    const PixelStatistics reference = renderTiles(none, integrator, key);
    for (const auto& [name, file] : {std::pair{"the default roulette", &atDefault},
                                     std::pair{"rr_depth 1, rr_threshold 1", &aggressive}}) {
      const PixelStatistics rendered = renderTiles(*file, integrator, key);
      EXPECT_NE(rendered.mean, reference.mean) << integrator << ": " << name << " ends no path";
      family.add(fmt::format("{}, {} against none", integrator, name), rendered, reference);
    }
  }
  EXPECT_EQ(family.decide("Russian roulette").rejections, 0);
}

}  // namespace
}  // namespace verity::validation
