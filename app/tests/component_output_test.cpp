// `verity render --strategies DIR` and `--path-lengths DIR` through the program: the files
// and manifest they write, their sums, and clear errors (non-zero exit, no crash) for an
// integrator that cannot split its image, a directory that cannot be written and both
// options at once.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "film/image_io.h"
#include "test_directory.h"
#include "testing/child_process.h"

namespace verity {
namespace {

const char* kScene = R"({
  "camera": {"transform": {"from": [0, 0, 4], "at": [0, 0, 0], "up": [0, 1, 0]}, "vfov": 40,
             "resolution": [16, 12]},
  "integrator": {"type": "bdpt", "max_bounces": 3},
  "surfaces": [
    {"type": "sphere", "radius": 1, "material": {"type": "lambertian", "albedo": 0.5}},
    {"type": "quad", "size": 2, "material": {"type": "diffuse light", "emit": 4},
     "transform": [{"axis": [1, 0, 0], "angle": 90}, {"translate": [0, 2, 0]}]}]
})";

class ComponentOutput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::freshTestDirectory("verity_component_output_");
    scene_ = (dir_ / "scene.json").string();
    std::ofstream(scene_) << kScene;
  }
  testing::Outcome render(std::vector<std::string> extra) {
    std::vector<std::string> args = {
        VERITY_BINARY, "render",     scene_, "--spp",
        "4",           "--variance", "-o",   (dir_ / "image.exr").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return testing::run(args);
  }
  // Σ of R over every pixel of `file`.
  static double sumOfRed(const std::filesystem::path& file) {
    const ImageChannels image = readExr(file);
    double sum = 0;
    for (float v : image.planes.at("R")) sum += v;
    return sum;
  }

  std::filesystem::path dir_;
  std::string scene_;
};

TEST_F(ComponentOutput, StrategiesWriteEveryStrategyAndAManifest) {
  const auto out = dir_ / "strategies";
  const auto outcome = render({"--strategies", out.string()});
  ASSERT_EQ(outcome.status, 0) << outcome.stderrText;
  std::ifstream in(out / "manifest.json");
  const nlohmann::json manifest = nlohmann::json::parse(in);
  EXPECT_EQ(manifest["kind"], "strategies");
  EXPECT_EQ(manifest["spp"], 4);
  EXPECT_EQ(manifest["max_bounces"], 3);
  // (s, t) with s ≥ 0, t ≥ 1 and s + t − 2 ≤ 3: 2 + 3 + 4 + 5 strategies, two images each.
  ASSERT_EQ(manifest["images"].size(), 28u);
  double weighted = 0;
  for (const auto& entry : manifest["images"]) {
    EXPECT_EQ(entry["s"].get<int>() + entry["t"].get<int>() - 2, entry["bounces"].get<int>());
    const auto file = out / entry["file"].get<std::string>();
    const ImageChannels image = readExr(file);
    EXPECT_EQ(image.planes.count("variance.R"), 1u) << file;
    EXPECT_EQ(image.planes.count("samples"), 1u) << file;
    if (entry["weighted"]) weighted += sumOfRed(file);
  }
  const double total = sumOfRed(dir_ / "image.exr");
  EXPECT_GT(total, 0);
  EXPECT_NEAR(weighted, total, 1e-5 * total);
}

TEST_F(ComponentOutput, PathLengthsOfThePathTracerAddUp) {
  const auto out = dir_ / "lengths";
  const auto outcome = render(
      {"--integrator", "path_tracer_mis", "--max-bounces", "5", "--path-lengths", out.string()});
  ASSERT_EQ(outcome.status, 0) << outcome.stderrText;
  std::ifstream in(out / "manifest.json");
  const nlohmann::json manifest = nlohmann::json::parse(in);
  EXPECT_EQ(manifest["kind"], "path_lengths");
  ASSERT_EQ(manifest["images"].size(), 6u);
  double sum = 0;
  for (const auto& entry : manifest["images"])
    sum += sumOfRed(out / entry["file"].get<std::string>());
  const double total = sumOfRed(dir_ / "image.exr");
  EXPECT_NEAR(sum, total, 1e-5 * total);
}

TEST_F(ComponentOutput, StrategiesNeedBdpt) {
  const auto outcome =
      render({"--integrator", "path_tracer_nee", "--strategies", (dir_ / "s").string()});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.stderrText.find("--strategies"), std::string::npos) << outcome.stderrText;
  EXPECT_NE(outcome.stderrText.find("bdpt"), std::string::npos) << outcome.stderrText;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "image.exr"));
}

TEST_F(ComponentOutput, PathLengthsNeedARadianceIntegrator) {
  const auto outcome = render({"--integrator", "ao", "--path-lengths", (dir_ / "k").string()});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.stderrText.find("--path-lengths"), std::string::npos) << outcome.stderrText;
}

TEST_F(ComponentOutput, UnwritableDirectoryIsAClearError) {
  std::ofstream(dir_ / "file") << "not a directory";
  const auto outcome = render({"--strategies", (dir_ / "file" / "out").string()});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.stderrText.find("cannot write"), std::string::npos) << outcome.stderrText;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "image.exr"));
}

TEST_F(ComponentOutput, TooManyImagesForMemoryIsAClearError) {
  const auto outcome = render({"--max-bounces", "100000", "--strategies", (dir_ / "s").string()});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.stderrText.find("GiB"), std::string::npos) << outcome.stderrText;
}

TEST_F(ComponentOutput, NotBothAtOnce) {
  const auto outcome =
      render({"--strategies", (dir_ / "s").string(), "--path-lengths", (dir_ / "k").string()});
  EXPECT_NE(outcome.status, 0);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "image.exr"));
}

}  // namespace
}  // namespace verity
