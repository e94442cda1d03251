// The referee through command templates: the fake renderer program (fake_renderer.cpp) run as
// processes, in parallel. Its images equal those made in the process for the same seeds, so
// the calibrations of calibration_test.cpp hold for this path; and its failures are errors
// naming the command and showing its stderr, or the file.
#include <gtest/gtest.h>

#include <filesystem>

#include "validation/referee/process_render_source.h"
#include "validation/referee/referee.h"
#include "validation/referee/tests/fake_images.h"

namespace verity::validation {
namespace {

class ProcessRender : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("verity_referee_process_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  static std::string fake(const std::string& extra = "") {
    return std::string(FAKE_RENDERER) + " --seed {seed} --out {out}" + extra;
  }
  std::string errorOf(ProcessRenderSource& source, const RefereeOptions& options) {
    try {
      referee(source, options);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }
  std::filesystem::path dir_;
};

TEST_F(ProcessRender, DecidesLikeTheSameRoundsInTheProcess) {
  RefereeOptions options;
  options.tileSize = 4;
  options.alpha = 0.05;
  options.margin = 0.05;
  options.initialRenders = 4;
  options.maxRenders = 128;
  options.seed = 1000;
  for (double bias : {0.0, 0.1}) {
    ProcessRenderSource processes({fake(), fake(" --bias " + std::to_string(bias))}, 4, dir_,
                                  std::nullopt);
    testing::FakeScene b;
    b.bias = bias;
    testing::FakeRenderSource memory({}, b);
    const RefereeResult viaProcesses = referee(processes, options);
    const RefereeResult inProcess = referee(memory, options);
    EXPECT_EQ(viaProcesses.verdictName(), bias == 0 ? "EQUIVALENT" : "DIFFER");
    EXPECT_EQ(viaProcesses.verdictName(), inProcess.verdictName());
    EXPECT_EQ(viaProcesses.rounds.size(), inProcess.rounds.size());
    // EXRs store floats, as the in-process images do: the same numbers.
    EXPECT_EQ(viaProcesses.comparison.tests[0].pooled.b.mean,
              inProcess.comparison.tests[0].pooled.b.mean);
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir_)) << "renders and logs are removed once read";
}

TEST_F(ProcessRender, AFailingCommandIsNamedWithItsStderr) {
  ProcessRenderSource source({fake(), fake(" --fail")}, 2, dir_, std::nullopt);
  const std::string error = errorOf(source, {});
  EXPECT_NE(error.find("side B"), std::string::npos) << error;
  EXPECT_NE(error.find("--fail"), std::string::npos) << error;
  EXPECT_NE(error.find("exited with status 7"), std::string::npos) << error;
  EXPECT_NE(error.find("fake renderer: failing as asked"), std::string::npos) << error;
}

TEST_F(ProcessRender, ACommandThatWritesNothingIsNamed) {
  ProcessRenderSource source({fake(), "true {seed} {out}"}, 2, dir_, std::nullopt);
  EXPECT_NE(errorOf(source, {}).find("wrote no"), std::string::npos);
}

TEST_F(ProcessRender, OutputsOfAnotherSizeOrWithoutRgbNameTheFile) {
  RefereeOptions options;
  options.tileSize = 4;
  ProcessRenderSource wide({fake(), fake(" --size 12 8")}, 2, dir_, std::nullopt);
  std::string error = errorOf(wide, options);
  EXPECT_NE(error.find("b-1.exr: 12x8 pixels, while side A has 8x8"), std::string::npos) << error;
  ProcessRenderSource grey({fake(), fake(" --no-rgb")}, 2, dir_, std::nullopt);
  error = errorOf(grey, options);
  EXPECT_NE(error.find(".exr: the image has no R, G and B"), std::string::npos) << error;
}

}  // namespace
}  // namespace verity::validation
