#include "stochastic_binding.h"

#include <pybind11/stl.h>

#include "check_options.h"
#include "python_bsdf.h"

namespace verity::python {

namespace {

chi2::StochasticCheck checkStochasticBsdf(py::object sample, py::object eval,
                                          const py::kwargs& kw) {
  const std::string check = checkName("check_stochastic_bsdf", kw);
  std::vector<std::string> known = kStochasticKeywords;
  known.push_back("wi");
  requireKnown(kw, check, known);
  const Eigen::Vector3d wi = readWi(kw, check);
  chi2::StochasticCheckOptions options;
  readStochasticOptions(kw, check, options);
  // The mean-weight check asks nothing of a pdf.
  const chi2::BsdfModel model = pythonBsdf(sample, eval, py::none(), wi, check);
  py::gil_scoped_release release;
  return chi2::checkStochasticBsdf(model, wi, options);
}

py::list albedo(const chi2::StochasticCheck& r) {
  py::list out;
  for (const chi2::WelchComparison& w : r.total) {
    py::dict d;
    d["sampled"] = w.sampled;
    d["sampled_error"] = w.sampledError;
    d["evaluated"] = w.evaluated;
    d["evaluated_error"] = w.evaluatedError;
    d["p_value"] = w.p;
    out.append(d);
  }
  return out;
}

}  // namespace

void bindStochastic(py::module_& m) {
  using chi2::StochasticCheck;
  py::class_<StochasticCheck>(m, "StochasticResult",
                              "What a mean-weight check found; str() is its report.")
      .def_property_readonly(
          "verdict", [](const StochasticCheck& r) { return chi2::verdictName(r.verdict()); },
          "'PASSED', 'FAILED' or 'INCONCLUSIVE'")
      .def_property_readonly("passed", &StochasticCheck::passed)
      .def_property_readonly("failures", &StochasticCheck::failures,
                             "'total albedo', 'cells', 'inconclusive' and per-sample defects")
      .def_property_readonly("inconclusive_reason", &StochasticCheck::inconclusiveReason)
      .def_property_readonly("samples", [](const StochasticCheck& r) { return r.samples; })
      .def_property_readonly("hits", [](const StochasticCheck& r) { return r.hits; })
      .def_property_readonly("albedo", &albedo,
                             "per component: sampled and evaluated means with their standard "
                             "errors, and Welch's p-value")
      .def_property_readonly("cells", [](const StochasticCheck& r) { return r.cells; })
      .def_property_readonly("cells_rejected",
                             [](const StochasticCheck& r) { return r.rejections; })
      .def_property_readonly("detectable_albedo_error",
                             [](const StochasticCheck& r) { return r.detectableTotal; })
      .def_property_readonly("detectable_cell_error",
                             [](const StochasticCheck& r) { return r.detectableCell; })
      .def_property_readonly("seconds", [](const StochasticCheck& r) { return r.seconds; })
      .def_property_readonly("report", &StochasticCheck::report)
      .def("__str__", &StochasticCheck::report)
      .def("__repr__", [](const StochasticCheck& r) {
        return "<verity.StochasticResult " + chi2::verdictName(r.verdict()) + ">";
      });
  m.def("check_stochastic_bsdf", &checkStochasticBsdf, py::arg("sample"), py::arg("eval"),
        R"(Checks a BSDF whose eval and sample weight are random, unbiased estimates (a layered
BSDF evaluated by a random walk), for one incident direction wi: on the sphere's cells, the
mean of weight over the draws that land in a cell against eval*|cos| integrated over it, by
Welch's test per cell with Holm's correction, and the total albedo.
    sample(wi, u) -> (wo, weight, pdf[, delta])  as for check_bsdf (pdf is not used)
    eval(wi, wo) -> (N,) or (N, 3)  an unbiased estimate of f without the cosine
The callables are called one batch at a time, in a fixed order.
Keywords: wi and alpha (required), name, samples, seed, resolution (0: 8 cells in cos theta),
power, strata (each cell's eval at strata x strata directions; even, default 32), threads.
Returns a StochasticResult.)");
}

}  // namespace verity::python
