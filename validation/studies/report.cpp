#include "validation/studies/report.h"

#include <fmt/format.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>

#include "core/error.h"
#include "validation/studies/json_lines.h"
#include "validation/studies/machine_info.h"
#include "validation/studies/summary.h"

namespace verity::studies {

namespace {

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'')
      q.append("'\\''");
    else
      q.push_back(c);
  }
  q.push_back('\'');
  return q;
}

}  // namespace

int makeReport(const std::vector<std::filesystem::path>& inputs,
               const std::filesystem::path& outDir) {
  std::vector<nlohmann::json> records;
  for (const auto& file : inputs) {
    if (!std::filesystem::exists(file)) throw VerityError(file.string(), "", "no such file");
    for (nlohmann::json& r : readJsonLines(file)) records.push_back(std::move(r));
  }
  if (records.empty()) throw VerityError("", "", "the results files hold no records");
  std::filesystem::create_directories(outDir);
  nlohmann::json summary = summarize(records);
  summary["text"] = summaryText(summary);
  summary["revision"] = sourceRevision();
  summary["created"] = timestamp();
  summary["machine"] = toJson(machineInfo());
  const std::filesystem::path summaryFile = outDir / "summary.json";
  {
    std::ofstream out(summaryFile);
    if (!out) throw VerityError(summaryFile.string(), "", "cannot write the summary");
    out << summary.dump(2) << '\n';
  }
  std::string command =
      fmt::format("{} {} --summary {} --out {}", VERITY_PYTHON, shellQuote(VERITY_REPORT_SCRIPT),
                  shellQuote(summaryFile.string()), shellQuote(outDir.string()));
  for (const auto& file : inputs) {
    command.push_back(' ');
    command.append(shellQuote(std::filesystem::absolute(file).string()));
  }
  const int status = std::system(command.c_str());
  if (status == -1) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

}  // namespace verity::studies
