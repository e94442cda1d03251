// `verity render` refuses what it cannot honour before it renders: an output it could not
// write (which would lose the render) and a bounce count beyond the supported limit.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "test_directory.h"
#include "testing/child_process.h"

namespace verity {
namespace {

class RenderCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::freshTestDirectory("verity_render_command_");
    scene_ = (dir_ / "scene.json").string();
    std::ofstream(scene_) << R"({
      "camera": {"transform": {"from": [0, 0, 4], "at": [0, 0, 0], "up": [0, 1, 0]},
                 "resolution": [8, 8]},
      "background": 1,
      "surfaces": [{"type": "sphere", "material": {"type": "lambertian", "albedo": 0.5}}]})";
  }
  testing::Outcome render(std::vector<std::string> extra) {
    std::vector<std::string> args = {VERITY_BINARY, "render", scene_, "--spp", "1"};
    args.insert(args.end(), extra.begin(), extra.end());
    return testing::run(args);
  }

  std::filesystem::path dir_;
  std::string scene_;
};

// A scene the loader warns about renders, with the warning on stderr; --strict refuses it.
TEST_F(RenderCommand, StrictMakesWarningsErrors) {
  const std::string warned = (dir_ / "warned.json").string();
  std::ofstream(warned) << R"({
      "camera": {"transform": {"from": [0, 0, 4], "at": [0, 0, 0], "up": [0, 1, 0]},
                 "resolution": [8, 8]},
      "background": 1,
      "surfaces": [{"type": "sphere", "material": {"type": "lambertian", "albedo": 1.5}}]})";
  const std::string out = (dir_ / "warned.exr").string();
  testing::Outcome r = testing::run({VERITY_BINARY, "render", warned, "--spp", "1", "-o", out});
  EXPECT_EQ(r.status, 0) << r.stderrText;
  EXPECT_NE(
      r.stderrText.find("warning: " + warned + ": surfaces[0].material.albedo: an albedo of 1.5"),
      std::string::npos)
      << r.stderrText;
  std::filesystem::remove(out);
  r = testing::run({VERITY_BINARY, "render", warned, "--spp", "1", "-o", out, "--strict"});
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.stderrText.find("--strict"), std::string::npos) << r.stderrText;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST_F(RenderCommand, WritesWhereAsked) {
  const auto outcome = render({"-o", (dir_ / "image.exr").string()});
  EXPECT_EQ(outcome.status, 0) << outcome.stderrText;
  EXPECT_TRUE(std::filesystem::exists(dir_ / "image.exr"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "image.exr.verity-probe"));
}

TEST_F(RenderCommand, MissingOutputDirectoryFailsBeforeRendering) {
  const auto outcome = render({"-o", (dir_ / "missing" / "image.exr").string()});
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.stderrText.find("-o: the output's directory does not exist"), std::string::npos)
      << outcome.stderrText;
  // The summary line of a finished render says "spp"; none must have run.
  EXPECT_EQ(outcome.stderrText.find("spp"), std::string::npos) << outcome.stderrText;
}

TEST_F(RenderCommand, OutputInsideAFileFailsBeforeRendering) {
  std::ofstream(dir_ / "file") << "not a directory";
  const auto outcome = render({"-o", (dir_ / "file" / "image.png").string()});
  EXPECT_EQ(outcome.status, 1);
  EXPECT_NE(outcome.stderrText.find("-o:"), std::string::npos) << outcome.stderrText;
}

TEST_F(RenderCommand, BounceCountBeyondTheLimitIsRejected) {
  // max_bounces + 2 vertices would overflow an int.
  const auto outcome = render(
      {"--integrator", "bdpt", "--max-bounces", "2147483646", "-o", (dir_ / "image.exr").string()});
  EXPECT_NE(outcome.status, 0);
  EXPECT_NE(outcome.stderrText.find("--max-bounces"), std::string::npos) << outcome.stderrText;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "image.exr"));
}

}  // namespace
}  // namespace verity
