// Reading the referee's JSON files (baselines, manifests) with errors that name the file.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace verity::validation {

// The parsed file. Throws VerityError naming the file when it is not a readable file ("cannot
// read the <what> (not a readable file)") or not JSON.
nlohmann::json readJsonFile(const std::filesystem::path& file, const std::string& what);

}  // namespace verity::validation
