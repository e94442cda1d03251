// The committed reports (reports/*/) stay readable by the program that redraws them: every
// results file there is read and summarized as `verity report` reads and summarizes it, so a
// record field that the summary starts to require, and that the committed files lack, fails
// here rather than in a user's `verity report`.
#include <gtest/gtest.h>

#include <filesystem>

#include "validation/studies/json_lines.h"
#include "validation/studies/summary.h"

namespace verity::studies {
namespace {

TEST(CommittedReports, EveryReportsResultsAreSummarized) {
  const std::filesystem::path reports = std::filesystem::path(VERITY_SOURCE_DIR) / "reports";
  int folders = 0;
  for (const auto& folder : std::filesystem::directory_iterator(reports)) {
    if (!folder.is_directory()) continue;
    SummaryRecords records;
    int files = 0;
    for (const auto& file : std::filesystem::directory_iterator(folder.path()))
      if (file.path().extension() == ".jsonl") {
        addSummaryRecords(readJsonLines(file.path()), file.path().string(), records);
        ++files;
      }
    if (files == 0) continue;
    ++folders;
    Summary summary;
    ASSERT_NO_THROW(summary = summarize(records)) << folder.path();
    EXPECT_FALSE(summary.convergence.empty()) << folder.path() << ": no convergence group";
  }
  // cornell-box, cornell-box-glass, glossy-cornell-box, samplers, veach-mats.
  EXPECT_GE(folders, 5);
}

}  // namespace
}  // namespace verity::studies
