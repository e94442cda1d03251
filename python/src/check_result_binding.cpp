#include "check_result_binding.h"

#include <pybind11/stl.h>
#include <verity/chi2/check_result.h>
#include <verity/chi2/figure_data.h>

namespace verity::python {

namespace py = pybind11;
using chi2::CheckResult;

void bindCheckResult(py::module_& m) {
  py::class_<CheckResult>(m, "Result", "What a check found; str() is its report.")
      .def_property_readonly(
          "verdict", [](const CheckResult& r) { return chi2::verdictName(r.verdict()); },
          "'PASSED', 'FAILED' or 'INCONCLUSIVE'")
      .def_property_readonly("passed", &CheckResult::passed)
      .def_property_readonly("failures", &CheckResult::failures,
                             "the names of the checks that failed")
      .def_property_readonly("inconclusive_reason",
                             [](const CheckResult& r) { return r.inconclusiveReason(); })
      .def_property_readonly("samples", [](const CheckResult& r) { return r.test.samples; })
      .def_property_readonly("valid", [](const CheckResult& r) { return r.test.valid; })
      .def_property_readonly("delta_samples", [](const CheckResult& r) { return r.deltaSamples; })
      .def_property_readonly("seconds", [](const CheckResult& r) { return r.test.seconds; })
      .def_property_readonly(
          "chi_square",
          [](const CheckResult& r) {
            const chi2::TestResult& t = r.test;
            py::dict d;
            d["ran"] = t.chiSquareRan();
            d["passed"] = t.chiSquarePassed();
            d["statistic"] = t.chiSquare.statistic;
            d["dof"] = t.chiSquare.dof;
            d["p_value"] = t.chiSquare.pValue;
            d["level"] = t.significance;
            d["cells"] = t.domain.cells();
            d["outside"] = t.outside;
            d["could_have_caught"] = t.chiSquareRan() ? t.chiSquarePower.describe() : "";
            return d;
          },
          "the chi-square test of the sampled directions against the integrated pdf")
      .def_property_readonly(
          "pdf_integral",
          [](const CheckResult& r) {
            const chi2::TestResult& t = r.test;
            py::dict d;
            d["ran"] = t.quadratureHolds();
            d["passed"] = t.integral.passed;
            d["integral"] = t.integral.integral;
            d["valid_fraction_interval"] = py::make_tuple(t.integral.lower, t.integral.upper);
            d["quadrature_error"] = t.quadratureError;
            d["could_have_caught"] = t.integralPower.describe();
            return d;
          },
          "the pdf's integral against the fraction of valid samples")
      .def_property_readonly(
          "defects",
          [](const CheckResult& r) {
            // The per-sample defects, of the histogrammed samples and the delta lobes.
            py::dict d;
            for (const chi2::Audit* audit : {&r.test.audit, &r.delta.audit})
              for (int k = 0; k < static_cast<int>(chi2::Defect::Count); ++k) {
                const auto defect = chi2::Defect(k);
                if (audit->count(defect) == 0) continue;
                py::dict e;
                e["count"] = audit->count(defect);
                e["first_example"] = audit->example(defect);
                e["worst_example"] = audit->worstExample(defect);
                if (!audit->worstExample(defect).empty()) {  // a comparison
                  e["classified"] = audit->classified(defect);
                  e["beyond_rounding"] = audit->beyondRounding(defect);
                  e["worst_beyond_rounding_example"] = audit->worstBeyondRoundingExample(defect);
                }
                const std::string name = chi2::defectName(defect);
                if (!d.contains(name)) d[name.c_str()] = e;
              }
            return d;
          },
          "{defect name: {'count', 'first_example', 'worst_example'}} for each defect found; a "
          "comparison (weight, sample pdf, reciprocity) adds 'classified', 'beyond_rounding' (how "
          "many of those classified rounding the directions do not explain) and the "
          "worst of those")
      .def_property_readonly(
          "compared_samples",
          [](const CheckResult& r) {
            py::dict d;
            d["samples"] = r.test.auditedSamples;
            d["reach"] = r.test.auditReach;
            d["power"] = r.test.auditPower;
            return d;
          },
          "the samples whose weight, sample pdf and reciprocity were compared ('samples': all "
          "unless audited_samples chose fewer), and 'reach', the least fraction of the samples a "
          "defect must touch to be met among them with probability 'power'")
      .def_property_readonly("report", &CheckResult::report)
      .def(
          "figure_json", [](const CheckResult& r) { return chi2::figureJson(r.test); },
          "the data of the check's figure (cells, observed and expected counts, verdicts) as "
          "JSON, which share/verity/plot_chi2.py draws")
      .def(
          "write_figure_data",
          [](const CheckResult& r, const std::string& path) {
            chi2::writeFigureData(r.test, path);
          },
          py::arg("path"),
          "writes figure_json() to path, for python3 <prefix>/share/verity/plot_chi2.py "
          "PATH PNG")
      .def("__str__", &CheckResult::report)
      .def("__repr__", [](const CheckResult& r) {
        return "<verity.Result " + chi2::verdictName(r.verdict()) + ">";
      });
}

}  // namespace verity::python
