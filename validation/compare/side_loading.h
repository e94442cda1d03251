// One side of `verity compare` from its files: one file is an image with variance channels
// (a Verity EXR rendered with --variance), several files are a set of independent renders
// from any renderer.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "validation/compare/comparison_side.h"

namespace verity::validation {

// `name` ("A" or "B") and `layer` (rgb_channels.h, for sets) as given on the command line.
// Throws VerityError naming the file: a single file without variance channels, a file
// without R, G and B, resolutions that differ within a set, no file at all.
std::unique_ptr<ComparisonSide> loadSide(const std::vector<std::filesystem::path>& files,
                                         const std::string& name, const std::string& layer);

}  // namespace verity::validation
