// An empty directory of its own for each test of the command line.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace verity::testing {

// <temp>/<prefix><current test's name>, emptied.
inline std::filesystem::path freshTestDirectory(const std::string& prefix) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      (prefix + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace verity::testing
