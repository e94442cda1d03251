// The referee's JUnit file (<verity/stats/junit.h> writes the XML).
#pragma once

#include <verity/stats/junit.h>

#include <filesystem>
#include <string>
#include <vector>

namespace verity::validation {

using stats::JunitCase;

// Throws VerityError naming the file when it cannot be written.
void writeJunit(const std::filesystem::path& file, const std::string& suite,
                const std::vector<JunitCase>& cases);

}  // namespace verity::validation
