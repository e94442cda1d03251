// JSON Lines files: the studies' records, one object per line, appended as runs finish.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

namespace verity::studies {

// A JSON Lines file as read: its records, and its last line if a run was cut off while
// writing it (a last line that neither parses nor ends in a newline).
struct JsonLinesFile {
  std::vector<nlohmann::json> records;
  std::optional<size_t> truncatedLine;  // 1-based line number
  uintmax_t completeBytes = 0;          // the length of the file up to that line
};

// Reads every line as one object. A line that is not a JSON object is an error naming the
// file and the line, except a truncated last line, which is returned for the caller to
// repair or refuse. A missing file holds no records.
JsonLinesFile readJsonLinesFile(const std::filesystem::path& file);
// The records; any corrupt line, a truncated last one included, is an error naming the file
// and the line.
std::vector<nlohmann::json> readJsonLines(const std::filesystem::path& file);
// Cuts the truncated last line of `read` (from readJsonLinesFile) off the file.
void removeTruncatedLine(const std::filesystem::path& file, const JsonLinesFile& read);
// Appends one line and flushes it to the file before returning.
void appendJsonLine(const std::filesystem::path& file, const nlohmann::json& record);

}  // namespace verity::studies
