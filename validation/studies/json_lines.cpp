#include "validation/studies/json_lines.h"

#include <fstream>

#include "core/error.h"

namespace verity::studies {

std::vector<nlohmann::json> readJsonLines(const std::filesystem::path& file) {
  std::vector<nlohmann::json> records;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      nlohmann::json j = nlohmann::json::parse(line);
      if (j.is_object()) records.push_back(std::move(j));
    } catch (const nlohmann::json::exception&) {
      // a line cut off by an interruption: that run is simply redone
    }
  }
  return records;
}

void appendJsonLine(const std::filesystem::path& file, const nlohmann::json& record) {
  // A torn last line (the process killed mid-write) must not glue onto this record.
  bool needNewline = false;
  {
    std::ifstream in(file, std::ios::binary | std::ios::ate);
    if (in && in.tellg() > 0) {
      in.seekg(-1, std::ios::end);
      needNewline = in.get() != '\n';
    }
  }
  std::ofstream out(file, std::ios::app);
  if (!out) throw VerityError(file.string(), "", "cannot append to the results file");
  if (needNewline) out << '\n';
  out << record.dump() << '\n';
  out.flush();
  if (!out) throw VerityError(file.string(), "", "cannot write to the results file");
}

}  // namespace verity::studies
