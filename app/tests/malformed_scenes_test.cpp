// Every scene of scenes/malformed/ is rejected with one line naming the file and the JSON
// path (or the line and column of a syntax error) and a non-zero exit: never a crash, never
// an image.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "testing/child_process.h"

namespace verity {
namespace {

struct MalformedCase {
  std::string file, expected;
};

void PrintTo(const MalformedCase& c, std::ostream* os) {
  *os << c.file;
}

std::vector<MalformedCase> loadCases() {
  std::vector<MalformedCase> cases;
  std::ifstream in(VERITY_SOURCE_DIR "/scenes/malformed/expected.tsv");
  std::string line;
  while (std::getline(in, line)) {
    const auto tab = line.find('\t');
    if (tab != std::string::npos) cases.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return cases;
}

class MalformedScene : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(MalformedScene, OneLineErrorNamingFileAndPath) {
  const std::string scene = std::string(VERITY_SOURCE_DIR "/scenes/malformed/") + GetParam().file;
  const auto output =
      std::filesystem::temp_directory_path() / ("malformed_" + GetParam().file + ".png");
  std::filesystem::remove(output);
  const auto outcome = testing::run({VERITY_BINARY, "render", scene, "-o", output.string()});
  EXPECT_EQ(outcome.status, 2) << outcome.stderrText;
  const std::string& err = outcome.stderrText;
  ASSERT_FALSE(err.empty());
  EXPECT_EQ(err.find('\n'), err.size() - 1) << "expected exactly one line:\n" << err;
  EXPECT_NE(err.find(scene), std::string::npos) << err;
  EXPECT_NE(err.find(GetParam().expected), std::string::npos)
      << "expected to find \"" << GetParam().expected << "\" in: " << err;
  EXPECT_FALSE(std::filesystem::exists(output)) << "no image may be written";
}

TEST(MalformedScenes, CorpusHasAtLeastFiftyCases) {
  EXPECT_GE(loadCases().size(), 50u);
}

INSTANTIATE_TEST_SUITE_P(Corpus, MalformedScene, ::testing::ValuesIn(loadCases()),
                         [](const auto& info) {
                           std::string name = info.param.file.substr(0, info.param.file.size() - 5);
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace verity
