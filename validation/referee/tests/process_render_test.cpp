// The referee through command templates: the fake renderer program (fake_renderer.cpp) run as
// processes, in parallel. Its images equal those made in the process for the same seeds, so
// the calibrations of calibration_test.cpp hold for this path; and its failures are errors
// naming the command and showing its stderr, or the file. Renders that hang, crash or write
// half a file end within their limits, and leave no process behind.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

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

// Whether a process whose command line holds `marker` is running (or a zombie not yet
// reaped): read from /proc.
bool running(const std::string& marker) {
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    std::ifstream file(entry.path() / "cmdline", std::ios::binary);
    const std::string cmdline((std::istreambuf_iterator<char>(file)), {});
    if (cmdline.find(marker) != std::string::npos) return true;
  }
  return false;
}

// Whether such a process is still running 5 s from now. A group killed a moment ago may not
// have been scheduled to die yet (once seen here on a loaded machine, 0.08 s into a test); a
// render the referee failed to end sleeps for 987 s.
bool outlives(const std::string& marker) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (running(marker)) {
    if (std::chrono::steady_clock::now() >= deadline) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST_F(ProcessRender, DecidesLikeTheSameRoundsInTheProcess) {
  RefereeOptions options;
  options.tileSize = 4;
  options.alpha = 0.05;
  options.margin = 0.05;
  options.initialRenders = 4;
  options.maxRenders = 128;
  options.seed = 1000;
  // Pixels of sd 0.1 rather than the fake's 0.25: equal sides decide in three rounds (16
  // renders a side) rather than six (128), still through rounds that double.
  testing::FakeScene a;
  a.noise = 0.1;
  const std::string quiet = " --noise " + std::to_string(a.noise);
  for (double bias : {0.0, 0.1}) {
    ProcessRenderSource processes({fake(quiet), fake(quiet + " --bias " + std::to_string(bias))}, 4,
                                  dir_, std::nullopt);
    testing::FakeScene b = a;
    b.bias = bias;
    testing::FakeRenderSource memory(a, b);
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

// A render that hangs (a shell waiting on a child) is killed with its process group once past
// its timeout, and the error names the command, its side and seed; the render of the other
// side in flight is stopped too. "sleep 987.25" marks the processes to look for.
TEST_F(ProcessRender, AHungRenderIsKilledWithItsGroupAndNamed) {
  ProcessRenderSource source({fake(), "sleep 987.25; " + fake()}, 2, dir_, std::nullopt, 1.0);
  const auto start = std::chrono::steady_clock::now();
  const std::string error = errorOf(source, {});
  EXPECT_LT(secondsSince(start), 30) << "the limit of 1 s per render did not hold";
  EXPECT_NE(error.find("side B (seed 1)"), std::string::npos) << error;
  EXPECT_NE(error.find("sleep 987.25"), std::string::npos) << error;
  EXPECT_NE(error.find("ran past its limit of 1 s per render"), std::string::npos) << error;
  EXPECT_FALSE(outlives("987.25")) << "the hung render's sleep outlived the referee";
}

// The budget ends the renders still running at its end: no decision (INCONCLUSIVE, with the
// reason), nothing left running.
TEST_F(ProcessRender, TheBudgetStopsTheRendersInFlight) {
  ProcessRenderSource source({"sleep 987.5; " + fake(), fake()}, 2, dir_, std::nullopt);
  RefereeOptions options;
  options.maxSeconds = 1;
  const auto start = std::chrono::steady_clock::now();
  const RefereeResult r = referee(source, options);
  EXPECT_LT(secondsSince(start), 30) << "--max-seconds 1 did not end the renders";
  EXPECT_EQ(r.verdictName(), "INCONCLUSIVE");
  EXPECT_TRUE(r.rounds.empty());
  EXPECT_NE(r.stopReason.find("--max-seconds 1 reached during round 1"), std::string::npos)
      << r.stopReason;
  EXPECT_NE(r.stopReason.find("sleep 987.5"), std::string::npos) << r.stopReason;
  EXPECT_FALSE(outlives("987.5")) << "a render outlived the budget";
}

// One render that fails stops the others in flight rather than waiting for them.
TEST_F(ProcessRender, AFailureStopsTheOtherRendersInFlight) {
  ProcessRenderSource source({"sleep 987.75; " + fake(), fake(" --fail")}, 2, dir_, std::nullopt);
  const auto start = std::chrono::steady_clock::now();
  const std::string error = errorOf(source, {});
  EXPECT_LT(secondsSince(start), 30);
  EXPECT_NE(error.find("exited with status 7"), std::string::npos) << error;
  EXPECT_FALSE(outlives("987.75"));
}

TEST_F(ProcessRender, ACrashIsNamedWithItsSignal) {
  ProcessRenderSource source({fake(), fake(" --crash")}, 2, dir_, std::nullopt);
  const std::string error = errorOf(source, {});
  EXPECT_NE(error.find("side B"), std::string::npos) << error;
  EXPECT_NE(error.find("ended by signal 6 (Aborted)"), std::string::npos) << error;
  EXPECT_NE(error.find("fake renderer: crashing as asked"), std::string::npos) << error;
}

TEST_F(ProcessRender, AHalfWrittenImageNamesTheCommand) {
  ProcessRenderSource source({fake(), fake(" --half")}, 2, dir_, std::nullopt);
  const std::string error = errorOf(source, {});
  EXPECT_NE(error.find("side B (seed 1)"), std::string::npos) << error;
  EXPECT_NE(error.find("--half"), std::string::npos) << error;
  EXPECT_NE(error.find("wrote an image that cannot be read"), std::string::npos) << error;
}

}  // namespace
}  // namespace verity::validation
