// verity.check_bsdf_family and verity.FamilyResult: the family check (family_check.h) of a
// BSDF given by a factory of check_bsdf's three callables.
#pragma once

#include <pybind11/pybind11.h>

namespace verity::python {

void bindFamily(pybind11::module_& m);

}  // namespace verity::python
