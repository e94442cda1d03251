// NumPy .npy output, read by the report generator.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

namespace verity::studies {

// Values in C order as a float16 NumPy .npy file (format 1.0), `shape` outermost axis first.
// The report's figures need no more precision, and the files are half the size of float32.
void writeHalfNpy(const std::filesystem::path& file, const std::vector<float>& values,
                  const std::vector<size_t>& shape);

}  // namespace verity::studies
