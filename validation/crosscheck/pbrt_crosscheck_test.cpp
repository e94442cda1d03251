// Ground truth from an independent renderer: pbrt-v3, built outside this repository,
// rendered each scene of scenes/crosscheck/ several times with independent seeds
// (references/crosscheck/README.md says how, and every model difference). Each of our
// integrators that converges there must agree with it:
//
//   - Per 16×16 tile and channel, a Welch t-test of our mean against pbrt's. Both sides are
//     batch means (batch_regions.h): ours from independent batches, pbrt's from its renders,
//     so the reference's own noise enters through its renders' spread (df = renders − 1).
//   - Our renders take the samplers independent, halton and sobol in turn along the scenes and
//     integrators (suite_samplers.h).
//   - One Holm family over every test of every scene and integrator: family-wise level 1%.
//   - Each comparison's relative difference of the whole image's mean, per channel, with its
//     standard error (the whole image as one batch region on both sides), is printed for the
//     table of reports/validation-findings.md.
// Seeds are fixed by the names of the scene, integrator and batch (hashString), never tuned.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "loader/scene_loader.h"
#include "peer_comparison.h"
#include "validation/compare/comparison_family.h"

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

TEST(PbrtCrosscheck, OurIntegratorsAgreeWithPbrt) {
  const PeerComparison setup{"pbrt-v3", "", kTileSize, kBatches, kBatchSpp};
  ComparisonFamily family(kFamilyWiseLevel);
  fmt::print(
      "| scene | integrator | sampler | image mean against pbrt-v3, R / G / B (± 1 s.e.) |\n");
  for (size_t s = 0; s < std::size(kCases); ++s) {
    const Case& c = kCases[s];
    const std::vector<std::filesystem::path> renders =
        peerRenders(kSource / "references" / "crosscheck" / c.scene, "pbrt-seed");
    ASSERT_EQ(renders.size(), 8u) << c.scene << ": pbrt renders missing";
    const std::filesystem::path scene =
        kSource / "scenes" / "crosscheck" / (std::string(c.scene) + ".json");
    EXPECT_EQ(
        compareWithPeer(setup, loadScene(scene), int(s), c.scene, renders, c.integrators, family),
        0u)
        << c.scene << ": invalid samples";
  }
  EXPECT_EQ(family.decide("against pbrt-v3").rejections, 0);
}

}  // namespace
}  // namespace verity::validation
