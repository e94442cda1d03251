// The study report: summary numbers from the C++ side (summary.h), plots and pages from
// reports/make_report.py (matplotlib), run by Debian's /usr/bin/python3.
#pragma once

#include <filesystem>
#include <vector>

namespace verity::studies {

// Reads every record of `inputs` (JSON Lines), writes <outDir>/summary.json and runs the
// report script, which writes index.html, summary.md and the PNG plots into outDir.
// Returns the script's exit status.
int makeReport(const std::vector<std::filesystem::path>& inputs,
               const std::filesystem::path& outDir);

}  // namespace verity::studies
