// verity.check_stochastic_bsdf and verity.StochasticResult: the mean-weight check
// (stochastic_check.h) of a BSDF whose eval and sample weight are random estimates, given as
// check_bsdf's sample and eval callables.
#pragma once

#include <pybind11/pybind11.h>
#include <verity/chi2/stochastic_check.h>

namespace verity::python {

void bindStochastic(pybind11::module_& m);

}  // namespace verity::python
