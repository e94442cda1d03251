// Two integrators, one scene: next-event estimation and multiple importance sampling are
// different estimators of the same image, so `compareImages` must find them in agreement;
// and the comparison, as configured (16×16 tiles, family-wise 1%), must detect one of them
// made 1% too bright, to show the test's power at this sample count.
#include <gtest/gtest.h>

#include <cstdio>

#include "film/image_io.h"
#include "integrators/integrator_settings.h"
#include "loader/scene_loader.h"
#include "render/renderer.h"
#include "validation/compare/comparison_report.h"
#include "validation/compare/exr_statistics.h"
#include "validation/compare/image_comparison.h"

namespace verity::validation {
namespace {

// A sphere on a floor under a small downward-facing area light (strategies differ most for
// small lights), a black background, direct and one-bounce indirect light.
const char* kScene = R"({
  "camera": {"transform": {"from": [0, 2.5, 5], "at": [0, 0.7, 0], "up": [0, 1, 0]}, "vfov": 40,
             "resolution": [32, 32]},
  "integrator": {"type": "path_tracer_nee", "max_bounces": 2},
  "materials": [
    {"name": "floor", "type": "lambertian", "albedo": 0.5},
    {"name": "ball", "type": "lambertian", "albedo": [0.7, 0.5, 0.3]},
    {"name": "light", "type": "diffuse light", "emit": 12}
  ],
  "surfaces": [
    {"type": "quad", "size": 8, "transform": {"axis": [1, 0, 0], "angle": -90}, "material": "floor"},
    {"type": "sphere", "radius": 0.8, "transform": {"translate": [0, 0.8, 0]}, "material": "ball"},
    {"type": "quad", "size": 1.5,
     "transform": [{"axis": [1, 0, 0], "angle": 90}, {"translate": [0.5, 3, 0.5]}],
     "material": "light"}
  ]
})";

constexpr int kSpp = 2048;

PixelStatistics renderImage(const char* integratorType, uint64_t seed) {
  SceneFile file = loadSceneText(kScene, "/tmp/validation-end-to-end.json");
  IntegratorSettings settings = file.integrator;
  settings.type = findIntegratorType(integratorType);
  const auto integrator = makeIntegrator(settings);
  Film film(file.scene->camera().resolution());
  RenderOptions options;
  options.samplesPerPixel = kSpp;
  file.sampler->setSeed(seed);
  const RenderStats stats = render(*file.scene, *integrator, *file.sampler, film, options);
  EXPECT_EQ(stats.invalidSamples, 0u);
  ImageChannels image = filmChannels(film, true);
  image.attributes["verity:seed"] = std::to_string(seed);
  return pixelStatistics(image, std::string(integratorType) + " seed " + std::to_string(seed));
}

class EndToEnd : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    nee_ = new PixelStatistics(renderImage("path_tracer_nee", 1));
    mis_ = new PixelStatistics(renderImage("path_tracer_mis", 2));
  }
  static void TearDownTestSuite() {
    delete nee_;
    delete mis_;
  }
  static PixelStatistics *nee_, *mis_;
};
PixelStatistics* EndToEnd::nee_ = nullptr;
PixelStatistics* EndToEnd::mis_ = nullptr;

TEST_F(EndToEnd, NeeAndMisAgree) {
  const ComparisonResult r = compareImages(*nee_, *mis_);
  std::printf("%s", comparisonSummary(r, 3).c_str());
  EXPECT_EQ(r.tilesTested, 4);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_FALSE(r.differ) << comparisonSummary(r);
}

TEST_F(EndToEnd, OnePercentBrightnessErrorIsDetected) {
  // The power the comparison predicts from these renders' variances must cover a 1% bias
  // before the detection means anything; then both directions must be caught.
  const ComparisonResult base = compareImages(*nee_, *mis_);
  std::printf("detectable uniform bias at %.0f%% power: %.3f%% (%d spp, 32x32 px)\n",
              100 * base.options.power, 100 * base.detectableBias, kSpp);
  ASSERT_LT(base.detectableBias, 0.01);
  const ComparisonResult brighterMis = compareImages(*nee_, scaledStatistics(*mis_, 1.01));
  EXPECT_TRUE(brighterMis.differ) << comparisonSummary(brighterMis);
  const ComparisonResult brighterNee = compareImages(scaledStatistics(*nee_, 1.01), *mis_);
  EXPECT_TRUE(brighterNee.differ) << comparisonSummary(brighterNee);
  std::printf(
      "1%% brighter MIS: smallest p %.3g, %d tests rejected; 1%% brighter NEE: smallest "
      "p %.3g, %d rejected\n",
      brighterMis.smallestP, brighterMis.holm.rejections, brighterNee.smallestP,
      brighterNee.holm.rejections);
}

}  // namespace
}  // namespace verity::validation
