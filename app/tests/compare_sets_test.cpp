// `verity compare` as a referee for sets of renders, run through its
// command line (exit status 0 agree, 1 differ, 2 bad input) on renders made here by Verity's
// own renderer: a floor of two lambertian halves under a quad light, direct light only
// (max_bounces 1, path_tracer_nee), 32×32 pixels, kSpp samples per pixel per render, kRenders
// renders per side, 8×8 tiles (16 tiles, 48 tests), Holm at family-wise level 1%.
// Seeds are fixed by name (hashString of "compare-sets <side> <render>"), never chosen.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <stb_image.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "compare_cli.h"
#include "core/hash.h"
#include "film/image_io.h"
#include "integrators/integrator_settings.h"
#include "loader/scene_loader.h"
#include "render/renderer.h"
#include "validation/compare/image_comparison.h"
#include "validation/compare/side_loading.h"
#include "validation/compare/z_score_image.h"

namespace verity::validation {
namespace {

namespace fs = std::filesystem;
using testing::CompareOutcome;
using testing::runCompare;
using testing::sideArguments;

constexpr int kSpp = 64;
constexpr int kRenders = 8;

// The right half's albedo is the parameter: 0.5, or 0.505 for a 1% change in one material.
// Camera straight down from y = 4 (vfov 40: the floor from x = -1.46 to 1.46 fills the
// image; the halves meet at x = 0, the image's middle column boundary, so tile columns 0-1
// see only the left material and 2-3 only the right); the light (2×2, facing down) at y = 5,
// behind the camera.
std::string scene(double rightAlbedo) {
  return fmt::format(R"({{
  "camera": {{"transform": {{"from": [0, 4, 0], "at": [0, 0, 0], "up": [0, 0, -1]}}, "vfov": 40,
             "resolution": [32, 32]}},
  "integrator": {{"type": "path_tracer_nee", "max_bounces": 1}},
  "materials": [
    {{"name": "left", "type": "lambertian", "albedo": 0.5}},
    {{"name": "right", "type": "lambertian", "albedo": {}}},
    {{"name": "light", "type": "diffuse light", "emit": 10}}
  ],
  "surfaces": [
    {{"type": "quad", "size": [2, 4],
      "transform": [{{"axis": [1, 0, 0], "angle": -90}}, {{"translate": [-1, 0, 0]}}], "material": "left"}},
    {{"type": "quad", "size": [2, 4],
      "transform": [{{"axis": [1, 0, 0], "angle": -90}}, {{"translate": [1, 0, 0]}}], "material": "right"}},
    {{"type": "quad", "size": 2,
      "transform": [{{"axis": [1, 0, 0], "angle": 90}}, {{"translate": [0, 5, 0]}}], "material": "light"}}
  ]
}})",
                     rightAlbedo);
}

Film render(double rightAlbedo, const std::string& seedName, int spp) {
  SceneFile file = loadSceneText(scene(rightAlbedo), "/tmp/compare-sets.json");
  const auto integrator = makeIntegrator(file.integrator);
  Film film(file.scene->camera().resolution());
  RenderOptions options;
  options.samplesPerPixel = spp;
  file.sampler->setSeed(hashString(seedName));
  const RenderStats stats = render(*file.scene, *integrator, *file.sampler, film, options);
  EXPECT_EQ(stats.invalidSamples, 0u);
  return film;
}

// R, G and B renamed to `layer`.R ... (as other renderers name them), plus other channels.
ImageChannels renamed(const ImageChannels& image, const std::string& layer) {
  ImageChannels out = image;
  for (const char* c : {"R", "G", "B"}) {
    out.planes.erase(c);
    out.planes[layer + "." + c] = image.planes.at(c);
  }
  return out;
}

class CompareSets : public ::testing::Test {
 protected:
  // Side A: float EXRs with R, G, B (as Verity and pbrt-v3 write them). Side B: half-float
  // EXRs with the layer-prefixed names default.R, ... Changed: the right half 1% brighter in
  // albedo. Variance: one Verity EXR with variance channels of kRenders × kSpp samples.
  static void SetUpTestSuite() {
    // One folder per process: ctest -j runs each test in a process of its own.
    dir_ = fs::temp_directory_path() / ("verity-compare-sets-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    for (int r = 0; r < kRenders; ++r) {
      const std::string a = (dir_ / fmt::format("a{}.exr", r)).string();
      writeExr(a, filmChannels(render(0.5, fmt::format("compare-sets A {}", r), kSpp), false));
      a_.push_back(a);
      const std::string b = (dir_ / fmt::format("b{}.exr", r)).string();
      writeExr(b,
               renamed(filmChannels(render(0.5, fmt::format("compare-sets B {}", r), kSpp), false),
                       "default"),
               true);
      b_.push_back(b);
      const std::string c = (dir_ / fmt::format("changed{}.exr", r)).string();
      writeExr(c,
               filmChannels(render(0.505, fmt::format("compare-sets changed {}", r), kSpp), false));
      changed_.push_back(c);
    }
    variance_ = (dir_ / "variance.exr").string();
    writeExr(variance_,
             filmChannels(render(0.5, "compare-sets variance image", kRenders * kSpp), true));
  }

  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static fs::path dir_;
  static std::vector<std::string> a_, b_, changed_;
  static std::string variance_;
};
fs::path CompareSets::dir_;
std::vector<std::string> CompareSets::a_, CompareSets::b_, CompareSets::changed_;
std::string CompareSets::variance_;

TEST_F(CompareSets, TwoSetsWithDifferentSeedsAgree) {
  std::vector<std::string> args = sideArguments(a_, b_);
  args.insert(args.end(), {"--tile", "8"});
  const CompareOutcome o = runCompare(args);
  EXPECT_EQ(o.status, 0) << o.text();
  EXPECT_NE(o.out.find(fmt::format("a set of {} renders", kRenders)), std::string::npos)
      << o.text();
  EXPECT_NE(o.out.find(fmt::format("df = {} - 1 = {}", kRenders, kRenders - 1)), std::string::npos)
      << o.text();
  EXPECT_NE(o.out.find("verdict: AGREE"), std::string::npos) << o.text();
}

TEST_F(CompareSets, VarianceImageAgainstASetAgrees) {
  std::vector<std::string> args = sideArguments({variance_}, b_);
  args.insert(args.end(), {"--tile", "8"});
  const CompareOutcome o = runCompare(args);
  EXPECT_EQ(o.status, 0) << o.text();
  EXPECT_NE(o.out.find("one image with variance channels"), std::string::npos) << o.text();
}

TEST_F(CompareSets, OnePercentChangeInOneMaterialIsRejected) {
  // The power calculation must first say that every test of the right half (tile columns
  // 2-3) detects a 1% bias with 90% probability at the Bonferroni level 1%/48; then the
  // change must be found there, and nowhere else (the left half did not change).
  const fs::path json = dir_ / "changed.json", png = dir_ / "changed.png";
  std::vector<std::string> args = sideArguments(a_, changed_);
  args.insert(args.end(), {"-o", json.string(), "--tile", "8", "--z-image", png.string()});
  const CompareOutcome o = runCompare(args);
  EXPECT_EQ(o.status, 1) << o.text();
  std::ifstream in(json);
  const nlohmann::json report = nlohmann::json::parse(in);
  ASSERT_EQ(report["tile_tests"].size(), 48u);
  EXPECT_EQ(report["side_a"]["df"], kRenders - 1);
  int rejectedRight = 0;
  double worstRightBias = 0;
  for (const auto& t : report["tile_tests"]) {
    const bool right = t["tile"][0].get<int>() >= 2;
    if (right) {
      ASSERT_FALSE(t["detectable_relative_bias"].is_null());
      worstRightBias = std::max(worstRightBias, t["detectable_relative_bias"].get<double>());
      rejectedRight += t["rejected"].get<bool>();
    } else {
      EXPECT_FALSE(t["rejected"].get<bool>()) << t.dump();
    }
  }
  std::printf(
      "%d spp x %d renders per side: largest detectable bias in the right half %.3f%%, "
      "%d of its 24 tests rejected\n",
      kSpp, kRenders, 100 * worstRightBias, rejectedRight);
  EXPECT_LT(worstRightBias, 0.01);
  EXPECT_GT(rejectedRight, 0);
  // The summary lists the rejected tiles, with the channels rejected.
  EXPECT_NE(o.out.find("rejected tiles (x,y channels): (2,0 "), std::string::npos) << o.text();
  EXPECT_EQ(o.out.find("(0,0 "), std::string::npos) << o.text();
  // The z-score picture is side A's mean image with the z-scores over it: the PNG is the
  // picture drawn from the same comparison and A's mean (not B's), red (B above A) and
  // outlined inside the right half's tile (3, 1), not outlined in the left half's (0, 1).
  EXPECT_NE(o.out.find("z_c = "), std::string::npos) << o.text();
  std::vector<fs::path> filesA(a_.begin(), a_.end()), filesB(changed_.begin(), changed_.end());
  const auto a = loadSide(filesA, "A", ""), b = loadSide(filesB, "B", "");
  const ComparisonResult result = compareSides(*a, *b, {8});
  const ZScorePicture picture =
      drawZScorePicture(result, a->meanImage(), fmt::format("A: mean of {} renders", kRenders));
  int w = 0, h = 0, n = 0;
  unsigned char* pixels = stbi_load(png.string().c_str(), &w, &h, &n, 3);
  ASSERT_NE(pixels, nullptr);
  ASSERT_EQ(w, picture.canvas.width());
  ASSERT_EQ(h, picture.canvas.height());
  EXPECT_TRUE(std::equal(picture.canvas.pixels().begin(), picture.canvas.pixels().end(), pixels));
  stbi_image_free(pixels);
  ASSERT_EQ(picture.scale, 8);  // 32 pixels enlarged to 256
  const auto tile = [&](int tx, int ty, int dx, int dy) {
    return picture.canvas.at(picture.zPanel.x0 + 64 * tx + dx, picture.zPanel.y0 + 64 * ty + dy);
  };
  const Rgb8 inside = tile(3, 1, 32, 32);
  EXPECT_GT(inside[0], inside[2] + 30) << int(inside[0]) << " " << int(inside[2]);
  EXPECT_EQ(tile(3, 1, 0, 0), (Rgb8{0, 0, 0}));
  EXPECT_NE(tile(0, 1, 0, 0), (Rgb8{0, 0, 0}));
}

}  // namespace
}  // namespace verity::validation
