// The files of a comparison must be distinct renders: the same file twice (one path written
// two ways, a link, or a byte-identical copy) would count one render as two independent ones.
#pragma once

#include <filesystem>
#include <vector>

namespace verity::validation {

// Throws VerityError naming both files when two of `files` are the same file or have the
// same bytes.
void requireDistinctFiles(const std::vector<std::filesystem::path>& files);

}  // namespace verity::validation
