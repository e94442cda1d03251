// The referee's and `verity chi2 --sweep`'s JUnit file (<verity/stats/junit.h> writes the XML).
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
// The same for a document already written (e.g. chi2::FamilyResult::junit).
void writeJunit(const std::filesystem::path& file, const std::string& xml);

}  // namespace verity::validation
