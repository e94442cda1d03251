// Ground truth from a second independent renderer: pbrt-v4, built outside
// this repository, rendered each twin scene of scenes/pbrt-v4/ (a .pbrt file and a .json
// file written from one description by make_scenes.py) 16 times with independent seeds
// (references/pbrt-v4/README.md says how, and why the grey scenes let pbrt-v4's spectral
// rendering be compared with our RGB). Each of our integrators that converges there must
// agree with it:
//
//   - Per 8×8 tile and channel (32×32 images), a Welch t-test of our mean against pbrt-v4's.
//     Both sides are batch means (batch_regions.h): ours from independent batches, pbrt-v4's
//     from its renders, so the reference's own noise enters through its renders' spread
//     (df = renders − 1).
//   - Our renders take the samplers independent, halton and sobol in turn along the scenes and
//     integrators (suite_samplers.h).
//   - One Holm family over every test of every scene and integrator: family-wise level 1%.
//   - Each comparison's relative difference of the whole image's mean, per channel, with its
//     standard error, is printed for reports/validation-findings.md.
// Seeds are fixed by the names of the scene, integrator and batch (hashString), never tuned.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "film/image_io.h"
#include "loader/scene_loader.h"
#include "peer_comparison.h"
#include "render/render_batches.h"
#include "validation/compare/batch_regions.h"
#include "validation/compare/comparison_family.h"

namespace verity::validation::pbrt4_crosscheck_test {
namespace {

constexpr int kTileSize = 8;
constexpr int kBatches = 16;
constexpr int kBatchSpp = 64;
constexpr double kFamilyWiseLevel = 0.01;

const std::filesystem::path kSource(VERITY_SOURCE_DIR);

struct Case {
  const char* scene;
  std::vector<const char*> integrators;
};

// The light tracer never sees the smooth glass sphere (a delta lobe), so it leaves out
// glass-box; in env-spheres it finds the ground only from a disk as wide as the 20×20 ground,
// so rarely that its comparison would have almost no power, and it is left out there too.
// path_tracer_nee leaves out env-spheres: there it finds the light that the rough glass
// sphere focuses onto the ground only through rare paths, so at 16 batches of 64 spp its
// batch means are heavy-tailed and their spread understates its variance. The first run of
// this test rejected its tile (2, 0) (1.9% dark, t = -6.7 on 15 df); two renders of 8,192
// spp with variance channels put that tile 0.6 and 1.2 standard errors from pbrt-v4's mean
// (references/pbrt-v4/README.md).
const Case kCases[] = {
    {"area-box",
     {"path_tracer_mats", "path_tracer_nee", "path_tracer_mis", "bdpt", "light_tracer"}},
    {"rough-glass-box",
     {"path_tracer_mats", "path_tracer_nee", "path_tracer_mis", "bdpt", "light_tracer"}},
    {"glass-box", {"path_tracer_mats", "path_tracer_nee", "path_tracer_mis", "bdpt"}},
    {"env-spheres", {"path_tracer_mats", "path_tracer_mis", "bdpt"}}};

std::vector<std::filesystem::path> pbrtRenders(const std::string& scene) {
  return peerRenders(kSource / "references" / "pbrt-v4" / scene / "path", "seed-");
}

TEST(Pbrt4Crosscheck, OurIntegratorsAgreeWithPbrt4) {
  const PeerComparison setup{"pbrt-v4", "pbrt-v4 ", kTileSize, kBatches, kBatchSpp};
  ComparisonFamily family(kFamilyWiseLevel);
  fmt::print(
      "| scene | integrator | sampler | image mean against pbrt-v4, R / G / B (± 1 s.e.) |\n");
  for (size_t s = 0; s < std::size(kCases); ++s) {
    const Case& c = kCases[s];
    const std::vector<std::filesystem::path> renders = pbrtRenders(c.scene);
    ASSERT_EQ(renders.size(), 16u) << c.scene << ": pbrt-v4 renders missing";
    const std::filesystem::path scene =
        kSource / "scenes" / "pbrt-v4" / (std::string(c.scene) + ".json");
    EXPECT_EQ(
        compareWithPeer(setup, loadScene(scene), int(s), c.scene, renders, c.integrators, family),
        0u)
        << c.scene << ": invalid samples";
  }
  EXPECT_EQ(family.decide("against pbrt-v4").rejections, 0);
}

// The comparison can fail: with the left sphere's GGX alpha 0.2 instead of pbrt-v4's 0.3 (the
// scene file otherwise unchanged), BDPT at the same batches differs from pbrt-v4's renders.
TEST(Pbrt4Crosscheck, ARoughGlassOfAnotherRoughnessIsRejected) {
  const std::filesystem::path path = kSource / "scenes" / "pbrt-v4" / "rough-glass-box.json";
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = "\"alpha\": 0.3", to = "\"alpha\": 0.2";
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, from.size(), to);
  const SceneFile file = loadSceneText(text, path);
  const std::vector<std::filesystem::path> renders = pbrtRenders("rough-glass-box");
  ASSERT_EQ(renders.size(), 16u);
  const Vector2i res = file.scene->camera().resolution();
  int tiles = 0;
  const std::vector<int> regionOf = tileRegions(res.x(), res.y(), kTileSize, &tiles);
  BatchRegions pbrt(regionOf, tiles, "rough-glass-box pbrt-v4");
  for (const std::filesystem::path& r : renders) pbrt.addBatch(readExr(r));
  const std::string key = "pbrt-v4 rough-glass-box alpha 0.2 bdpt";
  BatchRegions ours(regionOf, tiles, key);
  renderBatches(file, "bdpt", -1, kBatches, kBatchSpp, key,
                [&](const Film& film) { ours.addBatch(film); });
  ComparisonFamily family(kFamilyWiseLevel);
  family.add(key, pbrt.statistics(), ours.statistics());
  EXPECT_GT(family.decide("alpha 0.2 against pbrt-v4's 0.3").rejections, 0);
}

}  // namespace
}  // namespace verity::validation::pbrt4_crosscheck_test
