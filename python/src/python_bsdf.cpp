#include "python_bsdf.h"

#include <fmt/format.h>

#include <memory>

namespace verity::python {

namespace {

using chi2::BsdfUniforms;
using chi2::DirectionSample;

// The values of eval as C++ arrays of `components` entries (1 for an (N,) result).
std::vector<std::vector<py::ssize_t>> valueShapes(py::ssize_t n, int components) {
  if (components == 1) return {{n}, {n, 1}};
  return {{n, components}};
}

void readValues(const py::array_t<double>& a, std::vector<Eigen::ArrayXd>& out, int components) {
  const double* p = a.data();
  for (size_t k = 0; k < out.size(); ++k)
    out[k] = Eigen::Map<const Eigen::ArrayXd>(p + k * components, components);
}

}  // namespace

chi2::BsdfModel pythonBsdf(py::object sample, py::object eval, py::object pdf,
                           const Eigen::Vector3d& wi, const std::string& check) {
  // Shared, so that the check's copies of the model (made without the GIL) copy no Python
  // reference; the last owner is the caller's model, dropped with the GIL held.
  struct Callables {
    Callable sample, eval, pdf;
  };
  const auto fns =
      std::make_shared<const Callables>(Callables{{std::move(sample), check, "sample(wi, u)"},
                                                  {std::move(eval), check, "eval(wi, wo)"},
                                                  {std::move(pdf), check, "pdf(wi, wo)"}});
  const Callable& evalFn = fns->eval;
  chi2::BsdfModel m;
  {
    // Its number of components, from eval at the mirror direction.
    const Eigen::Vector3d w = wi.normalized(), mirror(-w.x(), -w.y(), w.z());
    py::gil_scoped_acquire gil;
    const py::array_t<double> f = readArray(
        evalFn,
        call(evalFn, py::make_tuple(toArray(w), toArray(std::vector<Eigen::Vector3d>{mirror}))),
        "its value", {{1}, {1, -1}});
    m.components = f.ndim() == 1 ? 1 : static_cast<int>(f.shape(1));
  }
  const int components = m.components;
  m.sampleBatch = [fns, components](const Eigen::Vector3d& wi, const std::vector<BsdfUniforms>& u,
                                    std::vector<std::optional<DirectionSample>>& out) {
    const Callable& sampleFn = fns->sample;
    const auto n = static_cast<py::ssize_t>(u.size());
    py::gil_scoped_acquire gil;
    py::array_t<double> us({n, py::ssize_t(3)});
    double* p = us.mutable_data();
    for (py::ssize_t k = 0; k < n; ++k) {
      p[3 * k] = u[k].lobe;
      p[3 * k + 1] = u[k].xy.x;
      p[3 * k + 2] = u[k].xy.y;
    }
    const py::object result = call(sampleFn, py::make_tuple(toArray(wi), us));
    if (!py::isinstance<py::tuple>(result) || (py::len(result) != 3 && py::len(result) != 4))
      throw py::type_error(fmt::format(
          "{}: sample(wi, u) returned {}, expected a tuple (wo, weight, pdf) or (wo, weight, "
          "pdf, delta)",
          sampleFn.check, py::str(py::type::of(result)).cast<std::string>()));
    const py::tuple t = result.cast<py::tuple>();
    const auto wo = readArray(sampleFn, t[0], "wo", {{n, 3}});
    const auto weight = readArray(sampleFn, t[1], "weight", valueShapes(n, components));
    const auto pdf = readArray(sampleFn, t[2], "pdf", {{n}});
    py::array_t<double> delta;
    if (t.size() == 4) delta = readArray(sampleFn, t[3], "delta", {{n}});
    requireNoNan(sampleFn, pdf, "pdf");
    const double *w = wo.data(), *pd = pdf.data(), *d = t.size() == 4 ? delta.data() : nullptr;
    for (py::ssize_t k = 0; k < n; ++k) {
      DirectionSample s;
      s.wo = Eigen::Vector3d(w[3 * k], w[3 * k + 1], w[3 * k + 2]);
      s.weight = Eigen::Map<const Eigen::ArrayXd>(weight.data() + k * components, components);
      s.pdf = pd[k];
      s.delta = d && d[k] != 0;
      out[k] = s;
    }
  };
  m.evalBatch = [fns, components](const std::vector<Eigen::Vector3d>& wi,
                                  const std::vector<Eigen::Vector3d>& wo,
                                  std::vector<Eigen::ArrayXd>& out) {
    const Callable& evalFn = fns->eval;
    const auto n = static_cast<py::ssize_t>(out.size());
    py::gil_scoped_acquire gil;
    // wo is always (N, 3); wi is (3,) when it is one direction for all, else (N, 3).
    const py::array_t<double> wiArray = wi.size() == 1 ? toArray(wi[0]) : toArray(wi);
    const py::array_t<double> woArray =
        wo.size() == 1 ? toArray(std::vector<Eigen::Vector3d>(out.size(), wo[0])) : toArray(wo);
    const py::array_t<double> f = readArray(evalFn, call(evalFn, py::make_tuple(wiArray, woArray)),
                                            "its value", valueShapes(n, components));
    requireNoNan(evalFn, f, "its value");
    readValues(f, out, components);
  };
  m.pdfBatch = [fns](const Eigen::Vector3d& wi, const std::vector<Eigen::Vector3d>& wo,
                     std::vector<double>& out) {
    const Callable& pdfFn = fns->pdf;
    const auto n = static_cast<py::ssize_t>(out.size());
    py::gil_scoped_acquire gil;
    const py::array_t<double> p =
        readArray(pdfFn, call(pdfFn, py::make_tuple(toArray(wi), toArray(wo))), "its value", {{n}});
    requireNoNan(pdfFn, p, "its value");
    std::copy(p.data(), p.data() + n, out.begin());
  };
  // The point-by-point forms, for any check that asks for one direction (a batch of one).
  m.sample = [batch = m.sampleBatch](const Eigen::Vector3d& wi, const BsdfUniforms& u) {
    std::vector<std::optional<DirectionSample>> s(1);
    batch(wi, {u}, s);
    return s[0];
  };
  m.eval = [batch = m.evalBatch](const Eigen::Vector3d& wi, const Eigen::Vector3d& wo) {
    std::vector<Eigen::ArrayXd> f(1);
    batch({wi}, {wo}, f);
    return f[0];
  };
  m.pdf = [batch = m.pdfBatch](const Eigen::Vector3d& wi, const Eigen::Vector3d& wo) {
    std::vector<double> p(1);
    batch(wi, {wo}, p);
    return p[0];
  };
  return m;
}

}  // namespace verity::python
