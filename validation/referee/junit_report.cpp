#include "validation/referee/junit_report.h"

#include <fmt/format.h>

#include <fstream>

#include "core/error.h"

namespace verity::validation {

std::string xmlEscaped(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        if (c >= 0x20 || c == '\n' || c == '\t' || c == '\r') out += char(c);
    }
  }
  return out;
}

void writeJunit(const std::filesystem::path& file, const std::string& suite,
                const std::vector<JunitCase>& cases) {
  int failures = 0, errors = 0;
  double seconds = 0;
  for (const JunitCase& c : cases) {
    failures += c.outcome == JunitCase::Outcome::Failure;
    errors += c.outcome == JunitCase::Outcome::Error;
    seconds += c.seconds;
  }
  std::ofstream out(file);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << fmt::format("<testsuites tests=\"{}\" failures=\"{}\" errors=\"{}\" time=\"{:.3f}\">\n",
                     cases.size(), failures, errors, seconds);
  out << fmt::format(
      "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\" skipped=\"0\" "
      "time=\"{:.3f}\">\n",
      xmlEscaped(suite), cases.size(), failures, errors, seconds);
  for (const JunitCase& c : cases) {
    out << fmt::format("    <testcase name=\"{}\" classname=\"{}\" time=\"{:.3f}\"",
                       xmlEscaped(c.name), xmlEscaped(suite), c.seconds);
    if (c.outcome == JunitCase::Outcome::Passed) {
      out << ">\n";
    } else {
      const char* tag = c.outcome == JunitCase::Outcome::Failure ? "failure" : "error";
      out << fmt::format(">\n      <{} type=\"{}\" message=\"{}\">{}</{}>\n", tag,
                         xmlEscaped(c.type), xmlEscaped(c.message), xmlEscaped(c.details), tag);
    }
    out << fmt::format("      <system-out>{}</system-out>\n    </testcase>\n",
                       xmlEscaped(c.outcome == JunitCase::Outcome::Passed ? c.details : ""));
  }
  out << "  </testsuite>\n</testsuites>\n";
  if (!out) throw VerityError(file.string(), "", "cannot write the JUnit report");
}

}  // namespace verity::validation
