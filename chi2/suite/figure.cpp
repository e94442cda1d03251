#include "chi2/suite/figure.h"

#include <fmt/format.h>
#include <verity/chi2/figure_data.h>

#include <filesystem>
#include <stdexcept>

#include "core/error.h"
#include "core/program_files.h"

namespace verity::chi2 {

std::string writeFigure(const TestResult& result, const std::string& prefix) {
  const std::string data = prefix + ".json", png = prefix + ".png";
  try {
    writeFigureData(result, data);
  } catch (const std::runtime_error&) {
    throw VerityError(data, "", "cannot write the chi-square histogram");
  }
  // The figure is a convenience, but a missing one is an error rather than a silent gap.
  std::filesystem::path python;
  try {
    python = findPythonWith("matplotlib", "draw the chi-square figure");
  } catch (const VerityError& e) {
    throw VerityError(data, "", e.problem() + "; the histogram is in this file");
  }
  const std::filesystem::path script = sharedProgramFile("plot_chi2.py");
  const int status = runProgram({python.string(), script.string(), data, png});
  if (status != 0)
    throw VerityError(data, "",
                      fmt::format("cannot draw the chi-square figure: {} {} failed (exit status "
                                  "{}); the histogram is in this file",
                                  python.string(), script.string(), status));
  return png;
}

}  // namespace verity::chi2
