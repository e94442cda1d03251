// verity.Result: what a check found (check_result.h) as Python reads it: .verdict,
// .passed, .failures, each statistical test with its statistic, each per-sample defect with
// its count and first example, and str() the C++ report().
#pragma once

#include <pybind11/pybind11.h>

namespace verity::python {

void bindCheckResult(pybind11::module_& m);

}  // namespace verity::python
