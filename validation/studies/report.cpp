#include "validation/studies/report.h"

#include <fstream>

#include "core/error.h"
#include "core/program_files.h"
#include "core/version.h"
#include "validation/studies/json_lines.h"
#include "validation/studies/machine_info.h"
#include "validation/studies/summary.h"

namespace verity::studies {

int makeReport(const std::vector<std::filesystem::path>& inputs,
               const std::filesystem::path& outDir) {
  SummaryRecords records;
  bool anyRecord = false;
  for (const auto& file : inputs) {
    if (!std::filesystem::exists(file)) throw VerityError(file.string(), "", "no such file");
    const std::vector<nlohmann::json> read = readJsonLines(file);
    anyRecord = anyRecord || !read.empty();
    addSummaryRecords(read, file.string(), records);
  }
  if (!anyRecord) {
    std::string files;
    for (const auto& file : inputs) files += (files.empty() ? "" : ", ") + file.string();
    throw VerityError(files, "", "no study records in these results files");
  }
  std::filesystem::create_directories(outDir);
  const Summary typed = summarize(records);
  nlohmann::json summary = toJson(typed);
  summary["text"] = summaryText(typed);
  summary["revision"] = kRevision;
  summary["created"] = timestamp();
  summary["machine"] = toJson(machineInfo());
  const std::filesystem::path summaryFile = outDir / "summary.json";
  {
    std::ofstream out(summaryFile);
    if (!out) throw VerityError(summaryFile.string(), "", "cannot write the summary");
    out << summary.dump(2) << '\n';
  }
  // The script and the Python that runs it are found at run time, beside the program.
  std::vector<std::string> command = {findPythonWith("matplotlib", "draw the report").string(),
                                      sharedProgramFile("make_report.py").string(),
                                      "--summary",
                                      summaryFile.string(),
                                      "--out",
                                      outDir.string()};
  for (const auto& file : inputs) command.push_back(std::filesystem::absolute(file).string());
  const int status = runProgram(command);
  return status < 0 ? 127 : status;
}

}  // namespace verity::studies
