#include "callback.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

namespace verity::python {

namespace {

std::string shapeText(const std::vector<py::ssize_t>& shape, py::ssize_t n = -1) {
  std::vector<std::string> parts;
  for (py::ssize_t s : shape) parts.push_back(s >= 0 ? std::to_string(s) : "N");
  std::string text =
      "(" + fmt::format("{}", fmt::join(parts, ", ")) + (shape.size() == 1 ? ",)" : ")");
  return n >= 0 ? text + fmt::format(" with N = {}", n) : text;
}

}  // namespace

py::object call(const Callable& c, const py::args& args) {
  try {
    py::object result = c.function(*args);
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    return result;
  } catch (py::error_already_set& e) {
    // The callable's own exception, traceback and all, as the cause of one naming the check.
    if (e.matches(PyExc_KeyboardInterrupt)) throw;
    py::raise_from(e, PyExc_RuntimeError,
                   fmt::format("{}: {} raised {}", c.check, c.signature, e.what()).c_str());
    throw py::error_already_set();
  }
}

py::array_t<double> readArray(const Callable& c, const py::handle& value, const std::string& what,
                              const std::vector<std::vector<py::ssize_t>>& shapes) {
  const std::string expected = [&] {
    std::vector<std::string> s;
    for (const auto& shape : shapes) s.push_back(shapeText(shape));
    return fmt::format("{}", fmt::join(s, " or "));
  }();
  if (!py::isinstance<py::array>(value) && !py::isinstance<py::float_>(value) &&
      !py::isinstance<py::int_>(value) && !py::isinstance<py::sequence>(value))
    throw py::type_error(fmt::format("{}: {} returned {} of type {}, expected an array of shape {}",
                                     c.check, c.signature, what,
                                     py::str(py::type::of(value)).cast<std::string>(), expected));
  const py::array raw = py::array::ensure(value);
  if (!raw) throw py::error_already_set();
  const char kind = raw.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
    throw py::type_error(
        fmt::format("{}: {} returned {} of dtype {}, expected float64 or float32 (or integers, or "
                    "bool for delta)",
                    c.check, c.signature, what, py::str(raw.dtype()).cast<std::string>()));
  std::vector<py::ssize_t> got(raw.shape(), raw.shape() + raw.ndim());
  for (const auto& shape : shapes) {
    if (shape.size() != got.size()) continue;
    bool match = true;
    for (size_t i = 0; i < shape.size(); ++i) match = match && (shape[i] < 0 || shape[i] == got[i]);
    if (!match) continue;
    auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(raw);
    if (!a) throw py::error_already_set();
    return a;
  }
  throw py::value_error(fmt::format("{}: {} returned {} of shape {}, expected {}", c.check,
                                    c.signature, what, shapeText(got), expected));
}

void requireNoNan(const Callable& c, const py::array_t<double>& a, const std::string& what) {
  const double* p = a.data();
  for (py::ssize_t k = 0; k < a.size(); ++k)
    if (std::isnan(p[k]))
      throw py::value_error(
          fmt::format("{}: {} returned NaN in {} (flat index {})", c.check, c.signature, what, k));
}

py::array_t<double> toArray(const std::vector<Eigen::Vector3d>& v) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), py::ssize_t(3)});
  double* p = a.mutable_data();
  for (size_t k = 0; k < v.size(); ++k)
    for (int i = 0; i < 3; ++i) p[3 * k + i] = v[k][i];
  return a;
}

py::array_t<double> toArray(const Eigen::Vector3d& v) {
  py::array_t<double> a(py::ssize_t(3));
  for (int i = 0; i < 3; ++i) a.mutable_data()[i] = v[i];
  return a;
}

}  // namespace verity::python
