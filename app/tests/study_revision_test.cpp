// A study record names the revision the program was built from, the one `verity --version`
// prints, whatever folder the program runs in: never the revision some source folder happens
// to be at when it runs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "test_directory.h"
#include "testing/child_process.h"

namespace verity {
namespace {

TEST(StudyRevision, RecordsNameTheRevisionVersionPrints) {
  const std::filesystem::path dir = testing::freshTestDirectory("verity_study_revision_");
  const std::filesystem::path version = dir / "version.txt", results = dir / "speedup.jsonl";
  const testing::Outcome printed = testing::run(
      {"/bin/sh", "-c", "cd / && '" VERITY_BINARY "' --version > '" + version.string() + "'"});
  ASSERT_EQ(printed.status, 0) << printed.stderrText;
  std::ifstream versionText(version);
  const std::string text(std::istreambuf_iterator<char>(versionText), {});
  std::smatch match;
  ASSERT_TRUE(std::regex_search(text, match, std::regex(R"(\(git ([0-9a-f]{12}|unknown)\))")))
      << text;

  const testing::Outcome study = testing::run(
      {"/bin/sh", "-c",
       "cd / && '" VERITY_BINARY "' study speedup '" VERITY_SOURCE_DIR
       "/scenes/cornell-box.json' --integrator path_tracer_nee --threads 1 --spp 1 --repeats 1 "
       "--resolution 8 -o '" +
           results.string() + "' > /dev/null"});
  ASSERT_EQ(study.status, 0) << study.stderrText;
  std::ifstream in(results);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(nlohmann::json::parse(line).at("revision"), match[1].str());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace verity
