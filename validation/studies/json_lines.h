// JSON Lines files: the studies' records, one object per line, appended as runs finish.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

namespace verity::studies {

// JSON Lines: every line one object. Unparsable lines (a run cut off mid-write) are skipped.
std::vector<nlohmann::json> readJsonLines(const std::filesystem::path& file);
// Appends one line and flushes it to the file before returning.
void appendJsonLine(const std::filesystem::path& file, const nlohmann::json& record);

}  // namespace verity::studies
