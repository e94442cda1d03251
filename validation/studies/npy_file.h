// NumPy .npy output, read by the report generator.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace verity::studies {

// A float32 array as a NumPy .npy file (format 1.0), shape (height, width).
void writeNpy(const std::filesystem::path& file, const std::vector<float>& data, int width,
              int height);
// Any array: `descr` its NumPy type ("<f4", "<f2"), `shape` outermost axis first, `bytes`
// of data in C order.
void writeNpy(const std::filesystem::path& file, const void* data, size_t bytes,
              const std::string& descr, const std::vector<size_t>& shape);

}  // namespace verity::studies
