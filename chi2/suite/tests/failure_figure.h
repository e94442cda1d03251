// A failing configuration's figure, for the failure message: the suite draws the histogram
// of every sampling test that fails into one directory, $VERITY_CHI2_FIGURES or else
// <build>/chi2-failures, named after the GoogleTest test (and a case label where one test
// runs several), so that a reader of the CI log finds the picture the message names.
#pragma once

#include <verity/chi2/sampling_check.h>

#include <string>

namespace verity::chi2::testing {

std::string failureFigureDirectory();

// Draws the figure and returns a line for the failure message naming it (or saying why it
// could not be drawn; the test fails on its own checks either way).
std::string failureFigure(const TestResult& result, const std::string& label = "");

}  // namespace verity::chi2::testing
