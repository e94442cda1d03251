// verity.compare in a module built without the image comparison (VERITY_CHECKS_ONLY: no
// validation/compare): the same signature, raising an error that says so.
#include "compare_binding.h"

namespace verity::python {

namespace py = pybind11;

void bindCompare(py::module_& m) {
  m.def(
      "compare",
      [](py::object, py::object, py::kwargs) {
        PyErr_SetString(PyExc_NotImplementedError,
                        "verity.compare: this verity module was built without the image "
                        "comparison (VERITY_CHECKS_ONLY); build Verity in full for it");
        throw py::error_already_set();
      },
      py::arg("a"), py::arg("b"),
      "Not available: this module was built without the image comparison (VERITY_CHECKS_ONLY).");
}

}  // namespace verity::python
