#include "validation/referee/junit_report.h"

#include <fstream>

#include "core/error.h"

namespace verity::validation {

void writeJunit(const std::filesystem::path& file, const std::string& suite,
                const std::vector<JunitCase>& cases) {
  std::ofstream out(file);
  out << stats::junitXml(suite, cases);
  if (!out) throw VerityError(file.string(), "", "cannot write the JUnit report");
}

}  // namespace verity::validation
