// The referee's parts: its schedule and seeds, command templates, tile moments against
// validation/compare's set of renders, baselines written and read back, and what it refuses.
#include "validation/referee/referee.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "validation/compare/render_set_side.h"
#include "validation/referee/baseline.h"
#include "validation/referee/command_template.h"
#include "validation/referee/moments_side.h"
#include "validation/referee/tests/fake_images.h"

namespace verity::validation {
namespace {

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(Referee, ScheduleDoublesUpToTheMaximumAndSeedsNeverRepeat) {
  RefereeOptions o;
  o.initialRenders = 4;
  o.maxRenders = 40;
  EXPECT_EQ(renderSchedule(o), (std::vector<int>{4, 8, 16, 32, 40}));
  o.maxRenders = 4;
  EXPECT_EQ(renderSchedule(o), (std::vector<int>{4}));
  std::set<uint64_t> seeds;
  for (int i = 0; i < 100; ++i)
    for (Side s : {Side::A, Side::B}) seeds.insert(renderSeed(7, s, i));
  EXPECT_EQ(seeds.size(), 200u);
}

TEST(Referee, OptionsOutOfRangeNameTheOption) {
  const auto refused = [](auto change) {
    RefereeOptions o;
    change(o);
    return errorOf([&] { checkRefereeOptions(o); });
  };
  EXPECT_NE(refused([](RefereeOptions& o) { o.margin = 0; }).find("--margin"), std::string::npos);
  EXPECT_NE(refused([](RefereeOptions& o) { o.alpha = 0.6; }).find("--alpha"), std::string::npos);
  EXPECT_NE(refused([](RefereeOptions& o) { o.initialRenders = 1; }).find("--initial-renders"),
            std::string::npos);
  EXPECT_NE(refused([](RefereeOptions& o) { o.maxRenders = 2; }).find("--max-renders"),
            std::string::npos);
  EXPECT_NE(refused([](RefereeOptions& o) { o.maxSeconds = -1; }).find("--max-seconds"),
            std::string::npos);
  EXPECT_EQ(refused([](RefereeOptions&) {}), "");
}

// A time budget ends the rounds: INCONCLUSIVE after the first round, saying why, naming the
// undecided tests and the margin that could have been claimed.
TEST(Referee, MaxSecondsEndsTheRoundsInconclusive) {
  testing::FakeRenderSource source({}, {});
  RefereeOptions options;
  options.tileSize = 4;
  options.maxRenders = 256;
  options.maxSeconds = 1e-9;
  const RefereeResult r = referee(source, options);
  EXPECT_EQ(r.verdictName(), "INCONCLUSIVE");
  EXPECT_EQ(r.rounds.size(), 1u);
  EXPECT_NE(r.stopReason.find("--max-seconds"), std::string::npos) << r.stopReason;
  EXPECT_FALSE(r.undecided.empty());
  EXPECT_GT(r.claimableMargin, options.margin);
  // The claimable margin is where every test passes at the last look's level.
  const double level = r.rounds.back().decision.equivalenceLevel;
  EXPECT_EQ(decideRound(r.comparison, std::min(0.999, r.claimableMargin), level).verdict,
            Verdict::Equivalent);
}

TEST(CommandTemplate, PlaceholdersAreCheckedAndFilledShellQuoted) {
  EXPECT_NE(errorOf([] { checkCommandTemplate("render --out {out}", "--a", 16); }).find("{seed}"),
            std::string::npos);
  EXPECT_NE(errorOf([] { checkCommandTemplate("render --seed {seed}", "--b", 16); }).find("--b"),
            std::string::npos);
  EXPECT_NE(errorOf([] { checkCommandTemplate("r {seed} {out} {spp}", "--a", {}); }).find("--spp"),
            std::string::npos);
  EXPECT_NE(errorOf([] { checkCommandTemplate("r {seed} {out} {sed}", "--a", 4); }).find("{sed}"),
            std::string::npos);
  EXPECT_EQ(errorOf([] { checkCommandTemplate("r {seed} {out} {spp}", "--a", 4); }), "");
  EXPECT_EQ(expandCommand("r -s {seed} -o {out} -n {spp}", 12, "/tmp/it's.exr", 64),
            "r -s 12 -o '/tmp/it'\\''s.exr' -n 64");
}

// Renders of seeds 1, 2, ... of the fake scene, both as images and added to moments.
struct FakeRenders {
  FakeRenders(const testing::FakeScene& scene, int count) : moments(scene.tileSize) {
    for (uint64_t seed = 1; seed <= uint64_t(count); ++seed) {
      images.push_back(testing::fakeRender(scene, seed));
      names.push_back("r" + std::to_string(seed));
      moments.add(images.back(), names.back());
    }
  }
  TileMoments moments;
  std::vector<ImageChannels> images;
  std::vector<std::string> names;
};

// The referee's moments give each tile the same estimate as `verity compare`'s set of renders
// (render_set_side.h: the method of batch means over the same pixels).
TEST(TileMoments, EstimatesEqualThoseOfASetOfRenders) {
  const testing::FakeScene scene;
  const FakeRenders renders(scene, 5);
  const TileMoments& moments = renders.moments;
  const RenderSetSide set(renders.names, renders.images, "");
  const TileGrid grid{scene.width, scene.height, scene.tileSize};
  const auto expected = set.tileEstimates(grid, set.usablePixels(2));
  const auto got = MomentsSide(moments, "A").tileEstimates(grid, {});
  for (int t = 0; t < grid.count(); ++t)
    for (int c = 0; c < kChannels; ++c) {
      // Welford's update and the batch sums round differently: relative 1e-12.
      EXPECT_NEAR(got[t][c].mean, expected[t][c].mean, 1e-12 * expected[t][c].mean);
      EXPECT_NEAR(got[t][c].variance, expected[t][c].variance, 1e-12 * expected[t][c].variance);
      EXPECT_NEAR(got[t][c].dfDenominator, expected[t][c].dfDenominator,
                  1e-12 * expected[t][c].dfDenominator);
    }
}

// The picture under the z-scores: each pixel's mean over the renders, as `verity compare`
// shows for a set; moments kept elsewhere (a baseline) have no pixels to show.
TEST(TileMoments, MeanImageIsThePixelMeanOfTheRenders) {
  const testing::FakeScene scene;
  const FakeRenders renders(scene, 3);
  const TileMoments& moments = renders.moments;
  const ImageChannels expected = RenderSetSide(renders.names, renders.images, "").meanImage();
  const ImageChannels got = MomentsSide(moments, "A").meanImage();
  ASSERT_EQ(got.width, scene.width);
  ASSERT_EQ(got.height, scene.height);
  for (const char* channel : {"R", "G", "B"}) {
    ASSERT_EQ(got.planes.count(channel), 1u) << channel;
    const std::vector<float>&g = got.planes.at(channel), &e = expected.planes.at(channel);
    ASSERT_EQ(g.size(), e.size());
    for (size_t i = 0; i < g.size(); ++i)
      EXPECT_NEAR(g[i], e[i], 1e-6f * std::abs(e[i])) << channel << " pixel " << i;
  }
  const TileMoments kept(
      moments.grid(), moments.renders(),
      std::vector<std::array<TileMoments::Moments, kChannels>>(moments.grid().count()));
  EXPECT_TRUE(kept.meanImage().planes.empty());
}

TEST(TileMoments, RefusesAnotherSizeAndNonFiniteValuesNamingTheFile) {
  testing::FakeScene scene;
  TileMoments moments(scene.tileSize);
  moments.add(testing::fakeRender(scene, 1), "first.exr");
  scene.width = 12;
  EXPECT_NE(errorOf([&] {
              moments.add(testing::fakeRender(scene, 2), "wide.exr");
            }).find("wide.exr: 12x8 pixels"),
            std::string::npos);
  scene.width = 8;
  ImageChannels bad = testing::fakeRender(scene, 3);
  bad.planes["G"][5] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(errorOf([&] { moments.add(bad, "nan.exr"); }).find("nan.exr: G of pixel (5, 0)"),
            std::string::npos);
  ImageChannels grey = testing::fakeRender(scene, 4);
  grey.planes.erase("B");
  EXPECT_NE(errorOf([&] { moments.add(grey, "grey.exr"); }).find("grey.exr"), std::string::npos);
}

class BaselineFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("verity_baseline_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(BaselineFile, RoundTripsEveryMomentAndTheSetup) {
  testing::FakeScene scene;
  Baseline b;
  b.scene = "fake";
  b.command = "fake --seed {seed} --out {out}";
  b.rendererVersion = "1.2";
  b.seed = 10;
  b.moments = TileMoments(scene.tileSize);
  for (uint64_t seed = 1; seed <= 6; ++seed)
    b.moments.add(testing::fakeRender(scene, seed), "r.exr");
  saveBaseline(dir_ / "base.json", b);
  const Baseline read = loadBaseline(dir_ / "base.json");
  EXPECT_EQ(read.scene, "fake");
  EXPECT_EQ(read.command, b.command);
  EXPECT_EQ(read.rendererVersion, "1.2");
  EXPECT_EQ(read.seed, 10u);
  ASSERT_EQ(read.moments.renders(), 6);
  for (int t = 0; t < b.moments.grid().count(); ++t)
    for (int c = 0; c < kChannels; ++c) {
      EXPECT_DOUBLE_EQ(read.moments.estimate(t, c).mean, b.moments.estimate(t, c).mean);
      EXPECT_NEAR(read.moments.estimate(t, c).variance, b.moments.estimate(t, c).variance,
                  1e-15 * b.moments.estimate(t, c).variance + 1e-300);
    }
  EXPECT_EQ(errorOf([&] { requireSameSetup(read, dir_ / "base.json", "fake", 4); }), "");
  EXPECT_NE(errorOf([&] { requireSameSetup(read, dir_ / "base.json", "other", 4); }).find("/scene"),
            std::string::npos);
  EXPECT_NE(
      errorOf([&] { requireSameSetup(read, dir_ / "base.json", "fake", 8); }).find("/tile_size"),
      std::string::npos);
  // Its renders had seeds 10, 12, ..., 20: new renders 11 + 2i never repeat them, 9 + 2i do.
  EXPECT_EQ(errorOf([&] { requireNewSeeds(read, dir_ / "base.json", 10, 64); }), "");
  EXPECT_NE(errorOf([&] { requireNewSeeds(read, dir_ / "base.json", 9, 64); }).find("/seed"),
            std::string::npos);
}

TEST_F(BaselineFile, MalformedFilesAreRefusedNamingWhere) {
  const auto refusal = [&](const std::string& text) {
    std::ofstream(dir_ / "b.json") << text;
    return errorOf([&] { loadBaseline(dir_ / "b.json"); });
  };
  EXPECT_NE(refusal("{").find("is not JSON"), std::string::npos);
  EXPECT_NE(refusal("{}").find("format"), std::string::npos);
  EXPECT_NE(refusal(R"({"format":"verity-referee-baseline","version":1,"scene":"s","command":"c",
      "renderer_version":"","seed":0,"width":8,"height":8,"tile_size":4,"renders":3,
      "tiles":[]})")
                .find("/tiles"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { loadBaseline(dir_ / "missing.json"); }).find("missing.json"),
            std::string::npos);
}

}  // namespace
}  // namespace verity::validation
