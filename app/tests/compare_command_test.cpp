// `verity compare` run as the program: its exit status reaches the shell through main()
// (0 agree, 1 differ, 2 bad input), for sets of renders given with -a and -b. The renders are
// constant images a fixed step above or below a level (deterministic, no random numbers), so
// each set's mean is known exactly; compare_inputs_test.cpp and compare_sets_test.cpp beside it
// test the statistics.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "film/image_io.h"
#include "test_directory.h"
#include "testing/child_process.h"

namespace verity {
namespace {

class CompareCommand : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::freshTestDirectory("verity_compare_command_"); }

  // `count` 8×8 renders NAME0.exr ...: render r is level ± step · (1 + r/2) everywhere (+ for
  // even r), so the set's mean is `level` (to float rounding) for an even count, and no two
  // renders are the same file (which compare refuses).
  std::vector<std::string> set(const std::string& name, int count, float level, float step) {
    std::vector<std::string> files;
    for (int r = 0; r < count; ++r) {
      ImageChannels image;
      image.width = image.height = 8;
      const float value = level + (r % 2 ? -step : step) * float(1 + r / 2);
      for (const char* c : {"R", "G", "B"}) image.planes[c].assign(64, value);
      files.push_back((dir_ / (name + std::to_string(r) + ".exr")).string());
      writeExr(files.back(), image);
    }
    return files;
  }
  testing::Outcome compare(const std::vector<std::string>& a, const std::vector<std::string>& b,
                           const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args = {VERITY_BINARY, "compare", "-a"};
    args.insert(args.end(), a.begin(), a.end());
    args.push_back("-b");
    args.insert(args.end(), b.begin(), b.end());
    args.insert(args.end(), extra.begin(), extra.end());
    return testing::run(args);
  }

  std::filesystem::path dir_;
};

TEST_F(CompareCommand, ExitStatusSaysAgreeDifferOrBadInput) {
  // Equal means (t = 0) agree; levels 1 and 2 with spreads of 1% differ.
  EXPECT_EQ(compare(set("a", 4, 1.0f, 0.01f), set("b", 4, 1.0f, 0.015f)).status, 0);
  EXPECT_EQ(compare(set("c", 4, 1.0f, 0.01f), set("d", 4, 2.0f, 0.01f)).status, 1);
  // Bad input: a missing file, a value that is no number.
  const testing::Outcome missing = compare({(dir_ / "none.exr").string()}, set("e", 2, 1, 0.1f));
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.stderrText.find("none.exr"), std::string::npos) << missing.stderrText;
  const testing::Outcome tile =
      compare(set("f", 2, 1, 0.1f), set("g", 2, 1, 0.2f), {"--tile", "x"});
  EXPECT_EQ(tile.status, 2);
  EXPECT_NE(tile.stderrText.find("--tile"), std::string::npos) << tile.stderrText;
}

}  // namespace
}  // namespace verity
