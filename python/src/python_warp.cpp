#include "python_warp.h"

#include <fmt/format.h>

#include <cmath>
#include <memory>

namespace verity::python {

chi2::WarpDomain warpDomain(const std::string& name) {
  using chi2::WarpDomain;
  if (name == "square") return WarpDomain::Square;
  if (name == "disk") return WarpDomain::Disk;
  if (name == "triangle") return WarpDomain::Triangle;
  if (name == "hemisphere") return WarpDomain::Hemisphere;
  if (name == "sphere") return WarpDomain::Sphere;
  throw py::value_error(fmt::format(
      "check_warp: domain '{}': expected square, disk, triangle, hemisphere or sphere", name));
}

chi2::WarpModel pythonWarp(chi2::WarpDomain domain, py::object sample, py::object pdf,
                           const std::string& check) {
  // Shared: the check copies the model without the GIL (python_bsdf.cpp).
  struct Callables {
    Callable sample, pdf;
  };
  const auto fns = std::make_shared<const Callables>(
      Callables{{std::move(sample), check, "sample(u)"}, {std::move(pdf), check, "pdf(points)"}});
  const py::ssize_t dims = chi2::isDirectional(domain) ? 3 : 2;
  chi2::WarpModel m;
  m.domain = domain;
  m.sampleBatch = [fns, dims](const std::vector<chi2::Uniform2>& u,
                              std::vector<std::optional<Eigen::Vector3d>>& out) {
    const auto n = static_cast<py::ssize_t>(u.size());
    py::gil_scoped_acquire gil;
    py::array_t<double> us({n, py::ssize_t(2)});
    double* p = us.mutable_data();
    for (py::ssize_t k = 0; k < n; ++k) p[2 * k] = u[k].x, p[2 * k + 1] = u[k].y;
    const auto points =
        readArray(fns->sample, call(fns->sample, py::make_tuple(us)), "its points", {{n, dims}});
    const double* q = points.data();
    for (py::ssize_t k = 0; k < n; ++k) {
      const double* r = q + dims * k;
      if (std::isnan(r[0]) && std::isnan(r[1])) {
        out[k].reset();
        continue;
      }
      out[k] = Eigen::Vector3d(r[0], r[1], dims == 3 ? r[2] : 0);
    }
  };
  m.pdfBatch = [fns, dims](const std::vector<Eigen::Vector3d>& points,
                           std::vector<double>& values) {
    const auto n = static_cast<py::ssize_t>(values.size());
    py::gil_scoped_acquire gil;
    py::array_t<double> a({n, dims});
    double* p = a.mutable_data();
    for (py::ssize_t k = 0; k < n; ++k)
      for (py::ssize_t i = 0; i < dims; ++i) p[dims * k + i] = points[k][i];
    const auto v = readArray(fns->pdf, call(fns->pdf, py::make_tuple(a)), "its value", {{n}});
    requireNoNan(fns->pdf, v, "its value");
    std::copy(v.data(), v.data() + n, values.begin());
  };
  m.sample = [batch = m.sampleBatch](const chi2::Uniform2& u) {
    std::vector<std::optional<Eigen::Vector3d>> p(1);
    batch({u}, p);
    return p[0];
  };
  m.pdf = [batch = m.pdfBatch](const Eigen::Vector3d& point) {
    std::vector<double> v(1);
    batch({point}, v);
    return v[0];
  };
  return m;
}

}  // namespace verity::python
