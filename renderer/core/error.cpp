#include "core/error.h"

namespace verity {

namespace {
std::string format(const std::string& file, const std::string& path, const std::string& problem) {
  std::string s;
  if (!file.empty()) s += file + ": ";
  if (!path.empty()) s += path + ": ";
  return s + problem;
}
}  // namespace

VerityError::VerityError(std::string file, std::string jsonPath, std::string problem)
    : std::runtime_error(format(file, jsonPath, problem)),
      file_(std::move(file)),
      jsonPath_(std::move(jsonPath)),
      problem_(std::move(problem)) {}

}  // namespace verity
