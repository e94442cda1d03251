// `verity render` refuses what it cannot honour before it renders: an output it could not
// write (which would lose the render; missing folders are created), an empty output name, variance
// channels asked of a PNG, a seed outside [0, 2⁶⁴ − 1] and a bounce count beyond the supported
// limit. And
// --explain describes the chosen integrator's strategies.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "integrators/integrator_registry.h"
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

// The rule of every command: missing folders on the way to an output are created.
TEST_F(RenderCommand, MissingOutputFoldersAreCreated) {
  const auto outcome = render({"-o", (dir_ / "missing" / "deeper" / "image.exr").string()});
  EXPECT_EQ(outcome.status, 0) << outcome.stderrText;
  EXPECT_TRUE(std::filesystem::exists(dir_ / "missing" / "deeper" / "image.exr"));
}

TEST_F(RenderCommand, OutputInsideAFileFailsBeforeRendering) {
  std::ofstream(dir_ / "file") << "not a directory";
  const auto outcome = render({"-o", (dir_ / "file" / "image.png").string()});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.stderrText.find("-o: cannot create the folder"), std::string::npos)
      << outcome.stderrText;
  // The summary line of a finished render says "spp"; none must have run.
  EXPECT_EQ(outcome.stderrText.find("spp"), std::string::npos) << outcome.stderrText;
}

TEST_F(RenderCommand, BounceCountBeyondTheLimitIsRejected) {
  // max_bounces + 2 vertices would overflow an int.
  const auto outcome = render(
      {"--integrator", "bdpt", "--max-bounces", "2147483646", "-o", (dir_ / "image.exr").string()});
  EXPECT_NE(outcome.status, 0);
  EXPECT_NE(outcome.stderrText.find("--max-bounces"), std::string::npos) << outcome.stderrText;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "image.exr"));
}

// Saturating or wrapping would render one image for many seeds.
TEST_F(RenderCommand, SeedOutsideItsRangeIsRefused) {
  for (const char* seed : {"-1", "18446744073709551616", "1e30", "2.5", "seven"}) {
    const auto outcome = render({"--seed", seed, "-o", (dir_ / "image.exr").string()});
    EXPECT_NE(outcome.status, 0) << seed;
    EXPECT_NE(outcome.stderrText.find("--seed"), std::string::npos) << outcome.stderrText;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "image.exr")) << seed;
  }
  const auto largest =
      render({"--seed", "18446744073709551615", "-o", (dir_ / "image.exr").string()});
  EXPECT_EQ(largest.status, 0) << largest.stderrText;
}

// An empty -o is not "no -o": it must not write <scene>.exr in the current directory.
TEST_F(RenderCommand, EmptyOutputNameIsRefused) {
  // In the test's directory, so that a default output would land there.
  const auto outcome = testing::run(
      {"/bin/sh", "-c",
       "cd '" + dir_.string() + "' && '" VERITY_BINARY "' render scene.json --spp 1 -o ''"});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.stderrText.find("-o: the name given is empty"), std::string::npos)
      << outcome.stderrText;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "scene.exr"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "scene.png"));
}

// An empty component folder is not "no component images": it would drop them in silence.
TEST_F(RenderCommand, EmptyComponentFolderIsRefused) {
  for (const char* option : {"--strategies", "--path-lengths"}) {
    const auto outcome =
        render({"--integrator", "bdpt", option, "", "-o", (dir_ / "image.exr").string()});
    EXPECT_EQ(outcome.status, 2) << option;
    EXPECT_NE(outcome.stderrText.find(std::string(option) + ": the name given is empty"),
              std::string::npos)
        << outcome.stderrText;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "image.exr")) << option;
  }
}

TEST_F(RenderCommand, VarianceOfAPngIsRefused) {
  const auto outcome = render({"--variance", "-o", (dir_ / "image.png").string()});
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.stderrText.find("--variance"), std::string::npos) << outcome.stderrText;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "image.png"));
}

// What `verity render --explain --integrator NAME` prints on stdout.
std::string explain(const std::filesystem::path& dir, const std::string& scene,
                    const std::string& integrator) {
  const std::filesystem::path out = dir / ("explain-" + integrator + ".txt");
  const auto outcome = testing::run({"/bin/sh", "-c",
                                     "'" VERITY_BINARY "' render '" + scene + "' --integrator " +
                                         integrator + " --explain > '" + out.string() + "'"});
  EXPECT_EQ(outcome.status, 0) << outcome.stderrText;
  std::ifstream in(out);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Each radiance integrator's explanation names its own strategies, and no two agree.
TEST_F(RenderCommand, ExplainDescribesTheChosenIntegrator) {
  std::vector<std::string> strategyLines;
  for (const std::string& name : radianceIntegrators()) {
    const std::string text = explain(dir_, scene_, name);
    EXPECT_NE(text.find("strategies: " + findIntegratorType(name)->strategies), std::string::npos)
        << name << ":\n"
        << text;
    const size_t at = text.find("strategies: ");
    ASSERT_NE(at, std::string::npos) << text;
    strategyLines.push_back(text.substr(at, text.find('\n', at) - at));
  }
  for (size_t i = 0; i < strategyLines.size(); ++i)
    for (size_t j = i + 1; j < strategyLines.size(); ++j)
      EXPECT_NE(strategyLines[i], strategyLines[j]);
  const std::string mats = explain(dir_, scene_, "path_tracer_mats");
  EXPECT_EQ(mats.find("next-event"), std::string::npos) << mats;
  const std::string normals = explain(dir_, scene_, "normals");
  EXPECT_NE(normals.find("strategies: none"), std::string::npos) << normals;
}

}  // namespace
}  // namespace verity
