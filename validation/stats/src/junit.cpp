#include <verity/stats/junit.h>

#include <iomanip>
#include <sstream>

namespace verity::stats {

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

std::string junitXml(const std::string& suite, const std::vector<JunitCase>& cases) {
  int failures = 0, errors = 0;
  double seconds = 0;
  for (const JunitCase& c : cases) {
    failures += c.outcome == JunitCase::Outcome::Failure;
    errors += c.outcome == JunitCase::Outcome::Error;
    seconds += c.seconds;
  }
  const std::string name = xmlEscaped(suite);
  std::ostringstream out;
  out << std::fixed << std::setprecision(3);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << "<testsuites tests=\"" << cases.size() << "\" failures=\"" << failures << "\" errors=\""
      << errors << "\" time=\"" << seconds << "\">\n";
  out << "  <testsuite name=\"" << name << "\" tests=\"" << cases.size() << "\" failures=\""
      << failures << "\" errors=\"" << errors << "\" skipped=\"0\" time=\"" << seconds << "\">\n";
  for (const JunitCase& c : cases) {
    out << "    <testcase name=\"" << xmlEscaped(c.name) << "\" classname=\"" << name
        << "\" time=\"" << c.seconds << "\">\n";
    if (c.outcome != JunitCase::Outcome::Passed) {
      const char* tag = c.outcome == JunitCase::Outcome::Failure ? "failure" : "error";
      out << "      <" << tag << " type=\"" << xmlEscaped(c.type) << "\" message=\""
          << xmlEscaped(c.message) << "\">" << xmlEscaped(c.details) << "</" << tag << ">\n";
    }
    out << "      <system-out>"
        << xmlEscaped(c.outcome == JunitCase::Outcome::Passed ? c.details : "")
        << "</system-out>\n    </testcase>\n";
  }
  out << "  </testsuite>\n</testsuites>\n";
  return out.str();
}

}  // namespace verity::stats
