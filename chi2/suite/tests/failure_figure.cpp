#include "failure_figure.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "chi2/suite/figure.h"

namespace verity::chi2::testing {

std::string failureFigureDirectory() {
  const char* dir = std::getenv("VERITY_CHI2_FIGURES");
  return dir && *dir ? dir : VERITY_CHI2_FAILURE_DIR;
}

std::string failureFigure(const TestResult& result, const std::string& label) {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  // "Quick/WarpTest" + "SamplesMatchPdf/uniform_sphere": one file name, no folders.
  std::string name = test ? std::string(test->test_suite_name()) + "." + test->name() : "chi2";
  if (!label.empty()) name += "." + label;
  std::replace(name.begin(), name.end(), '/', '-');
  try {
    std::filesystem::create_directories(failureFigureDirectory());
    const std::filesystem::path prefix = std::filesystem::path(failureFigureDirectory()) / name;
    return "  figure: " + writeFigure(result, prefix.string()) + "\n";
  } catch (const std::exception& e) {
    return std::string("  no figure: ") + e.what() + "\n";
  }
}

}  // namespace verity::chi2::testing
