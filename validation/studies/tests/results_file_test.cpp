// Results files with corrupt records: a line that is not a JSON object is
// an error naming the file and the line, wherever it is; a last line cut off mid-write
// (no newline) is an error for readers, and a resumed study removes it, says so, and redoes
// that run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "testing/error_of.h"
#include "validation/studies/budget.h"
#include "validation/studies/json_lines.h"
#include "validation/studies/study_records.h"

namespace verity::studies {
namespace {

namespace fs = std::filesystem;

fs::path writeFile(const std::string& name, const std::string& text) {
  const fs::path file =
      fs::path(testing::TempDir()) / ("verity-results-" + std::to_string(getpid()) + name);
  std::ofstream(file, std::ios::trunc | std::ios::binary) << text;
  return file;
}

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

const char* kRecord = R"({"study": "convergence", "run": 0})";

std::string keyOf(const FieldReader& r) {
  return std::to_string(r.integer("run"));
}

TEST(ResultsFile, CorruptLineInTheMiddleNamesFileAndLine) {
  const fs::path file = writeFile(
      "middle.jsonl", std::string(kRecord) + "\n" + R"({"study": "conv)" + "\n" + kRecord + "\n");
  const std::string error = errorOf([&] { readJsonLines(file); });
  EXPECT_NE(error.find(file.string()), std::string::npos) << error;
  EXPECT_NE(error.find("line 2"), std::string::npos) << error;
  // A resumed study refuses it too: only a last line can have been cut off by an interruption.
  EXPECT_NE(errorOf([&] { KeyedStudyOutput(file, "convergence", keyOf); }).find("line 2"),
            std::string::npos);
  fs::remove(file);
}

TEST(ResultsFile, LineThatIsNotAnObjectIsAnError) {
  const fs::path file = writeFile("array.jsonl", std::string(kRecord) + "\n[1, 2]\n");
  EXPECT_NE(errorOf([&] { readJsonLines(file); }).find("line 2"), std::string::npos);
  fs::remove(file);
}

TEST(ResultsFile, OnlyRecordTruncatedIsAnErrorNamingTheLine) {
  const fs::path file = writeFile("only.jsonl", R"({"study": "conv)");
  const std::string error = errorOf([&] { readJsonLines(file); });
  EXPECT_NE(error.find(file.string() + ": line 1: truncated"), std::string::npos) << error;
  fs::remove(file);
}

TEST(ResultsFile, ResumedStudyRemovesTruncatedLastLineAndSaysSo) {
  const std::string whole = std::string(kRecord) + "\n";
  const fs::path file = writeFile("torn.jsonl", whole + R"({"study": "convergence", "ru)");
  KeyedStudyOutput output(file, "convergence", keyOf);
  EXPECT_TRUE(output.has(nlohmann::json{{"run", 0}}));
  std::vector<std::string> said;
  output.repairTruncatedLine([&](const std::string& line) { said.push_back(line); });
  ASSERT_EQ(said.size(), 1u);
  EXPECT_NE(said[0].find(file.string() + ": line 2: removed a truncated record"), std::string::npos)
      << said[0];
  EXPECT_EQ(readAll(file), whole);
  output.append(nlohmann::json{{"study", "convergence"}, {"run", 1}});
  EXPECT_EQ(readJsonLines(file).size(), 2u);
  fs::remove(file);
}

TEST(ResultsFile, WholeFileIsLeftAlone) {
  const std::string text = std::string(kRecord) + "\n\n" + kRecord + "\n";
  const fs::path file = writeFile("whole.jsonl", text);
  KeyedStudyOutput output(file, "convergence", keyOf);
  std::vector<std::string> said;
  output.repairTruncatedLine([&](const std::string& line) { said.push_back(line); });
  EXPECT_TRUE(said.empty());
  EXPECT_EQ(readAll(file), text);
  EXPECT_EQ(readJsonLines(file).size(), 2u);
  fs::remove(file);
}

TEST(StudyBudgets, SppMustBeWholeNumbers) {
  EXPECT_NE(errorOf([] {
              checkBudgets(BudgetType::Spp, {4, 2.5});
            }).find("--spp"),
            std::string::npos);
  EXPECT_NE(errorOf([] { checkBudgets(BudgetType::Spp, {0}); }).find("positive"),
            std::string::npos);
  EXPECT_EQ(errorOf([] { checkBudgets(BudgetType::Spp, {1, 16}); }), "");
  EXPECT_EQ(errorOf([] { checkBudgets(BudgetType::Time, {0.5}); }), "");
}

}  // namespace
}  // namespace verity::studies
