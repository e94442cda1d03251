// The .npy writer against the NumPy format 1.0 layout and IEEE 754 binary16 bit patterns
// worked out by hand.
#include "validation/studies/npy_file.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace verity::studies {
namespace {

std::string readBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(NpyFile, WritesFloat16WithShapeAndAlignedHeader) {
  const auto file = std::filesystem::path(testing::TempDir()) / "npy_file_test.npy";
  // 1 = 0x3c00, −2 = 0xc000, 0.1 rounds to 0x2e66, 65504 = 0x7bff (largest finite),
  // 1e5 overflows to +inf = 0x7c00, 2^−24 = 0x0001 (smallest subnormal).
  writeHalfNpy(file, {1.0f, -2.0f, 0.1f, 65504.0f, 1e5f, 5.9604645e-8f}, {2, 3});
  const std::string bytes = readBytes(file);
  ASSERT_GE(bytes.size(), 10u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const size_t headerLength = uint8_t(bytes[8]) | (size_t(uint8_t(bytes[9])) << 8);
  const size_t dataStart = 10 + headerLength;
  EXPECT_EQ(dataStart % 64, 0u);
  const std::string header = bytes.substr(10, headerLength);
  EXPECT_NE(header.find("'descr': '<f2'"), std::string::npos) << header;
  EXPECT_NE(header.find("'shape': (2, 3)"), std::string::npos) << header;
  EXPECT_EQ(header.back(), '\n');
  ASSERT_EQ(bytes.size(), dataStart + 6 * 2);
  const std::vector<uint16_t> expected = {0x3c00, 0xc000, 0x2e66, 0x7bff, 0x7c00, 0x0001};
  for (size_t i = 0; i < expected.size(); ++i) {
    const uint16_t bits =
        uint8_t(bytes[dataStart + 2 * i]) | (uint16_t(uint8_t(bytes[dataStart + 2 * i + 1])) << 8);
    EXPECT_EQ(bits, expected[i]) << "value " << i;
  }
}

TEST(NpyFile, OneAxisShapeKeepsItsTupleComma) {
  const auto file = std::filesystem::path(testing::TempDir()) / "npy_file_test_1d.npy";
  writeHalfNpy(file, {0.5f, 0.25f, 2.0f}, {3});
  EXPECT_NE(readBytes(file).find("'shape': (3,)"), std::string::npos);
}

}  // namespace
}  // namespace verity::studies
