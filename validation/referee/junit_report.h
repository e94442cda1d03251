// JUnit XML as Jenkins and GitLab read it: one <testsuite> with one <testcase> per decision (a
// refereed comparison, a configuration of `verity chi2 --sweep`). EQUIVALENT or PASSED passes;
// DIFFER or FAILED is a <failure>; INCONCLUSIVE and bad input (a render command that failed) are
// an <error>, so that an undecided case never shows as passed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace verity::validation {

struct JunitCase {
  enum class Outcome { Passed, Failure, Error };
  std::string name;
  double seconds = 0;
  Outcome outcome = Outcome::Passed;
  std::string type;     // DIFFER, INCONCLUSIVE, bad input
  std::string message;  // one line
  std::string details;  // the summary, as the text of <failure> or <error>
};

// Throws VerityError naming the file when it cannot be written.
void writeJunit(const std::filesystem::path& file, const std::string& suite,
                const std::vector<JunitCase>& cases);

// `text` with &, <, >, " and ' escaped, and characters XML 1.0 forbids dropped.
std::string xmlEscaped(const std::string& text);

}  // namespace verity::validation
