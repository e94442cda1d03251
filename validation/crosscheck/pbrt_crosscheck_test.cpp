// Ground truth from an independent renderer (issue 17): pbrt-v3, built outside this repository,
// rendered each scene of scenes/crosscheck/ several times with independent seeds
// (references/crosscheck/README.md says how, and every model difference). Each of our
// integrators that converges there must agree with it:
//
//   - Per 16×16 tile and channel, a Welch t-test of our mean against pbrt's. Both sides are
//     batch means (batch_regions.h): ours from independent batches, pbrt's from its renders,
//     so the reference's own noise enters through its renders' spread (df = renders − 1).
//   - One Holm family over every test of every scene and integrator: family-wise level 1%.
//   - Each comparison's relative difference of the whole image's mean, per channel, with its
//     standard error (the whole image as one batch region on both sides), is printed for the
//     README's table.
// Seeds are fixed by the names of the scene, integrator and batch (hashString), never tuned.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "film/image_io.h"
#include "integrators/integrator_settings.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "validation/batch_regions.h"
#include "validation/comparison_family.h"
#include "validation/studies/seeds.h"
#include "validation/studies/timed_render.h"

namespace verity::validation {
namespace {

constexpr int kTileSize = 16;
constexpr int kBatches = 16;
constexpr int kBatchSpp = 16;
constexpr double kFamilyWiseLevel = 0.01;

const std::filesystem::path kSource(VERITY_SOURCE_DIR);

struct Case {
  const char* scene;
  std::vector<const char*> integrators;
};

// The light tracer reaches the camera only from surfaces with a non-delta lobe: it never sees
// the glass or the mirror sphere, so it leaves out the specular scene. There is no rough
// dielectric: pbrt-v3's is another model (references/crosscheck/README.md).
const Case kCases[] = {
    {"cornell-measured",
     {"path_tracer_mats", "path_tracer_nee", "path_tracer_mis", "bdpt", "light_tracer"}},
    {"cornell-measured-specular",
     {"path_tracer_mats", "path_tracer_nee", "path_tracer_mis", "bdpt"}},
    {"cornell-measured-ggx",
     {"path_tracer_mats", "path_tracer_nee", "path_tracer_mis", "bdpt", "light_tracer"}}};

std::vector<std::filesystem::path> pbrtRenders(const std::string& scene) {
  std::vector<std::filesystem::path> renders;
  const std::filesystem::path folder = kSource / "references" / "crosscheck" / scene;
  if (!std::filesystem::is_directory(folder)) return renders;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().extension() == ".exr" && entry.path().stem().string().starts_with("pbrt-seed"))
      renders.push_back(entry.path());
  std::sort(renders.begin(), renders.end());
  return renders;
}

// The relative difference of the whole image's mean (b − a) / a per channel, with its standard
// error, from two single-region batch statistics.
std::string relativeDifference(const PixelStatistics& a, const PixelStatistics& b) {
  std::string out;
  for (int c = 0; c < kChannels; ++c) {
    const double ma = a.mean[c][0], mb = b.mean[c][0];
    const double se = std::sqrt(a.variance[c][0] / a.samples[0] * mb * mb / (ma * ma) +
                                b.variance[c][0] / b.samples[0]) /
                      ma;
    out += fmt::format("{}{:+.2f}% ± {:.2f}%", c ? " / " : "", 100 * (mb / ma - 1), 100 * se);
  }
  return out;
}

TEST(PbrtCrosscheck, OurIntegratorsAgreeWithPbrt) {
  ComparisonFamily family(kFamilyWiseLevel);
  fmt::print("| scene | integrator | image mean against pbrt-v3, R / G / B (± 1 s.e.) |\n");
  for (const Case& c : kCases) {
    const std::vector<std::filesystem::path> renders = pbrtRenders(c.scene);
    ASSERT_EQ(renders.size(), 8u) << c.scene << ": pbrt renders missing";
    const SceneFile file =
        loadScene(kSource / "scenes" / "crosscheck" / (std::string(c.scene) + ".json"));
    const Vector2i res = file.scene->camera().resolution();
    int tiles = 0;
    const std::vector<int> regionOf = tileRegions(res.x(), res.y(), kTileSize, &tiles);
    // Tiles for the tests; the whole image as one region for the table.
    const std::vector<int> whole(regionOf.size(), 0);
    BatchRegions pbrt(regionOf, tiles, std::string(c.scene) + " pbrt-v3");
    BatchRegions pbrtImage(whole, 1, std::string(c.scene) + " pbrt-v3 image");
    for (const std::filesystem::path& r : renders) {
      const ImageChannels image = readExr(r);
      pbrt.addBatch(image);
      pbrtImage.addBatch(image);
    }
    for (const char* integratorName : c.integrators) {
      const std::string key = fmt::format("{} {}", c.scene, integratorName);
      BatchRegions ours(regionOf, tiles, key), oursImage(whole, 1, key + " image");
      const uint64_t invalid = studies::renderBatches(file, integratorName, -1, kBatches, kBatchSpp,
                                                      key, [&](const Film& film) {
                                                        ours.addBatch(film);
                                                        oursImage.addBatch(film);
                                                      });
      EXPECT_EQ(invalid, 0u) << key;
      fmt::print("| {} | {} | {} |\n", c.scene, integratorName,
                 relativeDifference(pbrtImage.statistics(), oursImage.statistics()));
      family.add(key, pbrt.statistics(), ours.statistics());
    }
  }
  EXPECT_EQ(family.decide("against pbrt-v3").rejections, 0);
}

}  // namespace
}  // namespace verity::validation
