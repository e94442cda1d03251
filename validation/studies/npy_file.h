// NumPy .npy output, read by the report generator.
#pragma once

#include <filesystem>
#include <vector>

namespace verity::studies {

// A float32 array as a NumPy .npy file (format 1.0), shape (height, width).
void writeNpy(const std::filesystem::path& file, const std::vector<float>& data, int width,
              int height);

}  // namespace verity::studies
