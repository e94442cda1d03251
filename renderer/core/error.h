// The one error type users see: names the file, the JSON path and the problem.
#pragma once

#include <stdexcept>
#include <string>

namespace verity {

class VerityError : public std::runtime_error {
 public:
  // `file` and `jsonPath` may be empty when the problem has no location.
  VerityError(std::string file, std::string jsonPath, std::string problem);

  const std::string& file() const { return file_; }
  const std::string& jsonPath() const { return jsonPath_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_, jsonPath_, problem_;
};

}  // namespace verity
