#include "validation/referee/junit_report.h"

#include <fstream>

#include "core/error.h"

namespace verity::validation {

void writeJunit(const std::filesystem::path& file, const std::string& suite,
                const std::vector<JunitCase>& cases) {
  writeJunit(file, stats::junitXml(suite, cases));
}

void writeJunit(const std::filesystem::path& file, const std::string& xml) {
  std::ofstream out(file);
  out << xml;
  if (!out) throw VerityError(file.string(), "", "cannot write the JUnit report");
}

}  // namespace verity::validation
