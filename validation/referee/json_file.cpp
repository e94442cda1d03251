#include "validation/referee/json_file.h"

#include <fmt/format.h>

#include <fstream>

#include "core/error.h"

namespace verity::validation {

nlohmann::json readJsonFile(const std::filesystem::path& file, const std::string& what) {
  const std::string name = file.string();
  std::ifstream in(file);
  if (!std::filesystem::is_regular_file(file) || !in)
    throw VerityError(name, "", fmt::format("cannot read the {} (not a readable file)", what));
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw VerityError(name, "", fmt::format("is not JSON: {}", e.what()));
  }
}

}  // namespace verity::validation
