#include "validation/studies/json_lines.h"

#include <fstream>

#include "core/error.h"

namespace verity::studies {

JsonLinesFile readJsonLinesFile(const std::filesystem::path& file) {
  JsonLinesFile read;
  std::ifstream in(file, std::ios::binary);
  std::string line;
  uintmax_t offset = 0;
  for (size_t number = 1; std::getline(in, line); ++number) {
    const bool lastWithoutNewline = in.eof();
    const uintmax_t start = offset;
    offset += line.size() + (lastWithoutNewline ? 0 : 1);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::string problem;
    try {
      nlohmann::json j = nlohmann::json::parse(line);
      if (j.is_object()) {
        read.records.push_back(std::move(j));
        continue;
      }
      problem = "the line is not a JSON object";
    } catch (const nlohmann::json::exception&) {
      // A run cut off mid-write leaves a last line without its newline.
      if (lastWithoutNewline) {
        read.truncatedLine = number;
        read.completeBytes = start;
        break;
      }
      problem = "corrupt record: not valid JSON";
    }
    throw VerityError(file.string(), "line " + std::to_string(number), problem);
  }
  return read;
}

std::vector<nlohmann::json> readJsonLines(const std::filesystem::path& file) {
  JsonLinesFile read = readJsonLinesFile(file);
  if (read.truncatedLine)
    throw VerityError(file.string(), "line " + std::to_string(*read.truncatedLine),
                      "truncated record (a run cut off while writing it); resuming the study "
                      "removes it and redoes that run");
  return std::move(read.records);
}

void removeTruncatedLine(const std::filesystem::path& file, const JsonLinesFile& read) {
  if (!read.truncatedLine) return;
  std::error_code error;
  std::filesystem::resize_file(file, read.completeBytes, error);
  if (error)
    throw VerityError(file.string(), "line " + std::to_string(*read.truncatedLine),
                      "cannot remove the truncated record: " + error.message());
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
