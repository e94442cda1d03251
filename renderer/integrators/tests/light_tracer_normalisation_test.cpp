// The scale of light paths connected to the camera (t = 1). A diffuse quad light faces a
// diffuse plane; the camera sees the plane and the light's emitting side. The light tracer
// (only t = 1 strategies, splatted) and bidirectional path tracing must match the path tracer
// region by region: any error in the importance normalisation over the image plane (area A,
// cos⁴θ, lens area), in the splat's per-pass scale or in the raster position would show as a
// brighter or darker, or shifted, image. Variants: pinhole, thin lens, a non-square image, a
// mirroring light transform (the front side must stay the emitting side) and a light facing
// away (one-sided emission: everything black but its back).
//
// Regions are 4×4 blocks of the image; estimates are per-pass block sums over independent
// passes (see bdpt_test_util.h); two-sided z-tests at family-wise level 1% with a Bonferroni
// correction over every comparison in this file.
#include <gtest/gtest.h>

#include "integrators/tests/bdpt_test_util.h"

namespace verity::light_tracer_normalisation_test {
namespace {

using bdpt_test::estimateRegions;

struct NormalisationCase {
  const char* name;
  std::string camera;  // the camera's JSON object body besides the transform
  std::string lightTransform;
  bool lightFacesPlane;
};

std::string sceneText(const NormalisationCase& c) {
  return R"({
  "camera": {"transform": {"from": [0, -3, 0.6], "at": [0, 0, 0.3], "up": [0, 0, 1]}, )" +
         c.camera + R"(},
  "sampler": {"type": "independent"},
  "materials": [
    {"name": "plane", "type": "lambertian", "albedo": [0.5, 0.6, 0.7]},
    {"name": "light", "type": "diffuse light", "emit": [8, 6, 4]}
  ],
  "surfaces": [
    {"type": "quad", "size": 4, "material": "plane"},
    {"type": "quad", "size": 0.6, "material": "light", "transform": )" +
         c.lightTransform + R"(}
  ]
})";
}

constexpr int kBlocks = 4;
constexpr int kVariants = 5;
// Two integrators against the path tracer, 16 blocks, 3 channels, 5 variants.
constexpr int kTests = 2 * kBlocks * kBlocks * 3 * kVariants;

void PrintTo(const NormalisationCase& c, std::ostream* os) {
  *os << c.name;
}

class LightTracerNormalisation : public ::testing::TestWithParam<NormalisationCase> {};

TEST_P(LightTracerNormalisation, MatchesPathTracerPerRegion) {
  const NormalisationCase& c = GetParam();
  const std::string text = sceneText(c);
  const Vector2i res = loadSceneText(text, "/tmp/n.json").scene->camera().resolution();
  const auto block = [&](int x, int y) {
    return (y * kBlocks / res.y()) * kBlocks + x * kBlocks / res.x();
  };
  const int regions = kBlocks * kBlocks;
  const auto reference = estimateRegions(text, "path_tracer_nee", 3, 200, 100, regions, block);
  const auto light = estimateRegions(text, "light_tracer", 3, 300, 200, regions, block);
  const auto bdpt = estimateRegions(text, "bdpt", 3, 150, 300, regions, block);
  const double z = bdpt_test::bonferroniZ(0.01, kTests);
  double litBlocks = 0;
  for (int r = 0; r < regions; ++r) {
    const std::string where = std::string(c.name) + ", block " + std::to_string(r);
    bdpt_test::expectSameMean(light[r], reference[r], z, "light tracer, " + where);
    bdpt_test::expectSameMean(bdpt[r], reference[r], z, "bdpt, " + where);
    litBlocks += reference[r].mean.sum() > 0;
    EXPECT_EQ(light[r].invalidSamples + bdpt[r].invalidSamples, 0u);
  }
  if (c.lightFacesPlane) {
    EXPECT_GE(litBlocks, 8) << "the plane and the light fill half the image";
  } else {
    EXPECT_EQ(litBlocks, 0) << "a light facing away lights nothing the camera sees";
  }
}

const char* kFacingDown = R"([{"axis": [1, 0, 0], "angle": 180}, {"translate": [0, 0.2, 1]}])";

INSTANTIATE_TEST_SUITE_P(
    Cameras, LightTracerNormalisation,
    ::testing::Values(
        NormalisationCase{"Pinhole", R"("vfov": 60, "resolution": [24, 24])", kFacingDown, true},
        NormalisationCase{"PinholeWide", R"("vfov": 45, "resolution": [40, 16])", kFacingDown,
                          true},
        NormalisationCase{"ThinLens",
                          R"("vfov": 60, "resolution": [24, 20], "aperture": 0.15, "fdist": 2.5)",
                          kFacingDown, true},
        NormalisationCase{
            "MirroredLight", R"("vfov": 60, "resolution": [24, 24])",
            R"([{"scale": [-1, 1, 1]}, {"axis": [1, 0, 0], "angle": 180}, {"translate": [0, 0.2, 1]}])",
            true},
        NormalisationCase{"LightFacingAway", R"("vfov": 60, "resolution": [24, 24])",
                          R"({"translate": [0, 0.2, 1]})", false}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace verity::light_tracer_normalisation_test
