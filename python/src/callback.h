// Calling a Python callable on a batch and reading what it returns, for the checks' batched
// forms. The checks run with the GIL released: each call takes it, calls once for the whole
// batch, checks for Ctrl-C, and reads the arrays back into C++ before it lets go. A callable
// that raises, or returns arrays of the wrong shape, dtype or with NaN, becomes a Python
// exception naming the check and the callable (the original's traceback chained to it), which
// the check passes up to its caller.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace verity::python {

namespace py = pybind11;

// What a call is, for messages: "check_bsdf 'name': sample(wi, u)".
struct Callable {
  py::object function;
  std::string check;      // e.g. "check_bsdf 'ggx'"
  std::string signature;  // e.g. "sample(wi, u)"
};

// Calls it with the arguments, the GIL held; raises (py::error_already_set) with the check
// named when the callable raises or Ctrl-C was pressed.
py::object call(const Callable& c, const py::args& args);

// The result (or element `index` of a returned tuple, named `what`) as a C-contiguous float64
// array of one of the shapes given (each a list of sizes, -1 for any); float32 is converted.
// ValueError or TypeError naming the callable, the expected shapes and the shape received
// otherwise, and for NaN where `finite` (Inf and negative values are the audit's to report).
py::array_t<double> readArray(const Callable& c, const py::handle& value, const std::string& what,
                              const std::vector<std::vector<py::ssize_t>>& shapes);

// (N, 3) directions or points, for passing to a callable.
py::array_t<double> toArray(const std::vector<Eigen::Vector3d>& v);
py::array_t<double> toArray(const Eigen::Vector3d& v);

// Raises ValueError if any value of the array is NaN, naming the callable and the first index.
void requireNoNan(const Callable& c, const py::array_t<double>& a, const std::string& what);

}  // namespace verity::python
