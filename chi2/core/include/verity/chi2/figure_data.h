// The data of one sampling test's figure, as JSON: the cells (every strip's edges, so that
// equal-probability cells are drawn as the rectangles they are), the observed and expected
// counts as rows of constant cell index j (numpy's (ny, nx) layout), every check's verdict and
// the chi-square p-value. plot_chi2.py, installed in share/verity beside the package, draws it:
//   python3 <prefix>/share/verity/plot_chi2.py PREFIX.json PREFIX.png
// so that a check outside Verity draws the figure Verity's own suite draws.
#pragma once

#include <verity/chi2/sampling_check.h>

#include <string>

namespace verity::chi2 {

// The figure's data as a JSON document.
std::string figureJson(const TestResult& result);

// Writes figureJson(result) to `path`; std::runtime_error naming the path when it cannot.
void writeFigureData(const TestResult& result, const std::string& path);

}  // namespace verity::chi2
