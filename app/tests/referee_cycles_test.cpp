// `verity referee` driving Blender's Cycles headless (scenes/cycles/), where Blender is
// installed: an option that removes energy (indirect light clamped at 1) DIFFERs from the
// default, and a scene script that refuses its options fails the render with the command
// named. Skipped, saying so, where no `blender` is on PATH (scripts/bootstrap does not install
// it; CTest reports the test as skipped).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "test_directory.h"
#include "testing/child_process.h"

namespace verity {
namespace {

// The first executable `blender` on PATH, or "".
std::string findBlender() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(dir) / "blender";
    if (!dir.empty() && access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return "";
}

class RefereeOnCycles : public ::testing::Test {
 protected:
  void SetUp() override {
    blender_ = findBlender();
    if (blender_.empty())
      GTEST_SKIP() << "blender is not installed (apt-get install blender): the referee's Cycles "
                      "test did not run";
    dir_ = testing::freshTestDirectory("verity_referee_cycles_");
  }
  void TearDown() override {
    if (!dir_.empty()) std::filesystem::remove_all(dir_);
  }
  // The Cycles box of scenes/cycles/ with `options` after the scene's own.
  std::string cycles(const std::string& options = "") const {
    return blender_ + " -b --factory-startup --python-exit-code 2 --python " +
           std::string(VERITY_SCENES_DIR) + "/cycles/glossy-glass-box.py -- --seed {seed} --spp " +
           "{spp} --out {out}" + options;
  }
  testing::Outcome referee(const std::string& a, const std::string& b) const {
    return testing::run({VERITY_BINARY, "referee", "--a", a, "--b", b, "--spp", "16", "--margin",
                         "0.01", "--max-renders", "8", "--jobs", "2", "--render-timeout", "300",
                         "--work-dir", (dir_ / "work").string()});
  }
  std::string blender_;
  std::filesystem::path dir_;
};

TEST_F(RefereeOnCycles, ClampingIndirectLightDiffers) {
  const testing::Outcome o = referee(cycles(), cycles(" --clamp-indirect 1"));
  EXPECT_EQ(o.status, 1) << o.stderrText;
}

TEST_F(RefereeOnCycles, AScriptThatRefusesItsOptionsFailsTheRenderByName) {
  const testing::Outcome o = referee(cycles(), cycles(" --pattern bogus"));
  EXPECT_EQ(o.status, 2) << o.stderrText;
  EXPECT_NE(o.stderrText.find("side B"), std::string::npos) << o.stderrText;
  EXPECT_NE(o.stderrText.find("--pattern bogus` exited with status 2"), std::string::npos)
      << o.stderrText;
  EXPECT_NE(o.stderrText.find("invalid choice: 'bogus'"), std::string::npos) << o.stderrText;
}

}  // namespace
}  // namespace verity
