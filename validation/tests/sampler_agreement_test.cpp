// Every sampler estimates the same image: renders with the stratified, halton and sobol
// samplers agree with renders with independent samples by per-tile Welch t-tests.
//
//   - cornell-box at 32 pixels wide, max_bounces 5, for the path tracers, BDPT and the light
//     tracer;
//   - per 16×16 tile and channel, batch means of 16 renders of 4 spp per side, each batch with
//     its own seed: for the correlated samplers that is an independent randomization of their
//     scrambles, so the spread of the batch means is an honest variance (a pixel's own samples
//     would overstate it);
//   - one Holm family over every test of every sampler and integrator: family-wise level 1%.
// Seeds are fixed by the sampler's and the integrator's names (hashString).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "loader/scene_loader.h"
#include "tile_batches.h"
#include "validation/compare/comparison_family.h"
#include "validation/compare/suite_samplers.h"

namespace verity::validation::sampler_agreement_test {
namespace {

constexpr int kWidth = 32;
constexpr int kTileSize = 16;
constexpr int kMaxBounces = 5;
constexpr int kBatches = 16;
constexpr int kBatchSpp = 4;
constexpr double kFamilyWiseLevel = 0.01;

SceneFile sceneWithSampler(const std::string& sampler) {
  SceneFile file =
      loadScene(std::filesystem::path(VERITY_SOURCE_DIR) / "scenes" / "cornell-box.json",
                SceneOverrides::atWidth(kWidth));
  useSampler(file, sampler, kBatchSpp);
  return file;
}

PixelStatistics renderTiles(const SceneFile& file, const std::string& integrator,
                            const std::string& key) {
  return testing::renderTileBatches(file, integrator, kMaxBounces, kBatches, kBatchSpp, kTileSize,
                                    key);
}

TEST(SamplerAgreement, EverySamplerEstimatesTheIndependentSamplersImage) {
  const SceneFile independent = sceneWithSampler("independent");
  ComparisonFamily family(kFamilyWiseLevel);
  for (const char* integrator :
       {"path_tracer_mats", "path_tracer_nee", "path_tracer_mis", "bdpt", "light_tracer"}) {
    const PixelStatistics reference = renderTiles(
        independent, integrator, fmt::format("sampler agreement independent {}", integrator));
    for (const char* sampler : {"stratified", "halton", "sobol"}) {
      const PixelStatistics tested =
          renderTiles(sceneWithSampler(sampler), integrator,
                      fmt::format("sampler agreement {} {}", sampler, integrator));
      family.add(fmt::format("{}, {} against independent", integrator, sampler), tested, reference);
    }
  }
  EXPECT_EQ(family.decide("samplers against independent samples").rejections, 0);
}

}  // namespace
}  // namespace verity::validation::sampler_agreement_test
