// Russian roulette's starting depth ("rr_depth") changes the images of every integrator that
// walks paths, but not what they estimate: renders with the roulette from the first bounce
// (rr_depth 1) and from the default depth agree by per-tile Welch t-tests.
//
//   - cornell-box at 32 pixels wide, max_bounces 5 (paths of up to 5 bounces, so roulette
//     decides at 1 to 5 bounces with rr_depth 1 and at 3 to 5 with the default);
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

TEST(RussianRoulette, DepthChangesImagesNotTheirExpectation) {
  const std::filesystem::path scene =
      std::filesystem::path(VERITY_SOURCE_DIR) / "scenes" / "cornell-box.json";
  SceneFile atDefault = loadScene(scene, SceneOverrides::atWidth(kWidth));
  SceneFile atFirst = loadScene(scene, SceneOverrides::atWidth(kWidth));
  ASSERT_EQ(atDefault.integrator.rrDepth, kDefaultRouletteDepth);
  atFirst.integrator.rrDepth = 1;
  ComparisonFamily family(kFamilyWiseLevel);
  for (const char* integrator :
       {"path_tracer_mats", "path_tracer_nee", "path_tracer_mis", "bdpt", "light_tracer"}) {
    const std::string key = fmt::format("roulette {}", integrator);
    const PixelStatistics a = renderTiles(atDefault, integrator, key);
    const PixelStatistics b = renderTiles(atFirst, integrator, key);
    EXPECT_NE(a.mean, b.mean) << integrator << ": rr_depth 1 should change the image";
    family.add(fmt::format("{}, rr_depth {} against 1", integrator, kDefaultRouletteDepth), a, b);
  }
  EXPECT_EQ(family.decide("Russian roulette from the first bounce").rejections, 0);
}

}  // namespace
}  // namespace verity::validation
