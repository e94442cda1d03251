// verity.compare(a, b, tile=16, alpha=0.01, margin=None, power=0.9): `verity compare -a ... -b
// ...` on two sets of renders given as arrays or as EXR files read by the command's own code
// (validation/compare/compare_decision.h, side_loading.h), and its result, verity.Comparison.
// Without the image comparison (a VERITY_CHECKS_ONLY build), compare_unavailable.cpp defines a
// verity.compare that says so.
#pragma once

#include <pybind11/pybind11.h>

namespace verity::python {

void bindCompare(pybind11::module_& m);

}  // namespace verity::python
