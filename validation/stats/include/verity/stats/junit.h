// JUnit XML as Jenkins and GitLab read it: one <testsuite> with one <testcase> per decision (a
// refereed comparison, a configuration of a chi-square family). A pass passes; a rejection
// (DIFFER, FAILED) is a <failure>; an undecided case (INCONCLUSIVE) or bad input (a render
// command that failed) is an <error>, so that it never shows as passed.
#pragma once

#include <string>
#include <vector>

namespace verity::stats {

struct JunitCase {
  enum class Outcome { Passed, Failure, Error };
  std::string name;
  double seconds = 0;
  Outcome outcome = Outcome::Passed;
  std::string type;     // DIFFER, FAILED, INCONCLUSIVE, bad input
  std::string message;  // one line
  std::string details;  // the summary: the text of <failure> or <error>, else <system-out>
};

// The whole document, for a suite named `suite`.
std::string junitXml(const std::string& suite, const std::vector<JunitCase>& cases);

// `text` with &, <, >, " and ' escaped, and characters XML 1.0 forbids dropped.
std::string xmlEscaped(const std::string& text);

}  // namespace verity::stats
