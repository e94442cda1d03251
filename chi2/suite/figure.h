// The picture of one sampling test: its histogram and verdicts are written as JSON
// (<verity/chi2/figure_data.h>, in the package), and chi2/core/plot_chi2.py (run by the first
// Python with matplotlib, and found in share/verity beside the program's bin folder:
// core/program_files.h) draws them as one figure:
// observed and expected counts side by side on one logarithmic colour scale, the standardised
// difference (O − E)/√E on a diverging scale, the axes named from the domain (φ and cos θ on the
// sphere, x and y on the square and disk, b₀ and b₁ on the triangle) and the configuration, verdict
// and p-value in the title. There is no fallback drawing: without Python or matplotlib writeFigure
// fails with an error naming what is missing.
#pragma once

#include <verity/chi2/sampling_check.h>

#include <string>

namespace verity::chi2 {

// Writes PREFIX.json (writeFigureData) and draws PREFIX.png from it; returns the PNG's path.
// Throws VerityError when the figure cannot be drawn (the JSON is kept).
std::string writeFigure(const TestResult& result, const std::string& prefix);

}  // namespace verity::chi2
