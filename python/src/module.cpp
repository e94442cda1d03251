// The Python module `verity`: Verity's checks for BSDFs and warps written in NumPy (or
// anything that takes and returns arrays), through batched callables, with the C++
// adapters' conventions (bsdf_adapter.h, warp_adapter.h). docs/python.md shows it in use.
#include <fmt/format.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <verity/chi2/quadrature.h>
#include <verity/chi2/warp_adapter.h>

#include "check_options.h"
#include "check_result_binding.h"
#include "compare_binding.h"
#include "family_binding.h"
#include "python_bsdf.h"
#include "python_warp.h"
#include "stochastic_binding.h"

namespace verity::python {

namespace {

// Runs the check with the GIL released: only the callables' batches take it.
template <class Check>
chi2::CheckResult released(const Check& check) {
  py::gil_scoped_release release;
  return check();
}

chi2::CheckResult checkBsdf(py::object sample, py::object eval, py::object pdf,
                            const py::kwargs& kw) {
  const std::string check = checkName("check_bsdf", kw);
  std::vector<std::string> known = kCheckKeywords;
  known.insert(known.end(), kBsdfKeywords.begin(), kBsdfKeywords.end());
  known.insert(known.end(), {"wi", "exterior_index", "interior_index"});
  requireKnown(kw, check, known);
  const Eigen::Vector3d wi = readWi(kw, check);
  chi2::BsdfCheckOptions options;
  readBsdfOptions(kw, check, options);
  chi2::BsdfModel model = pythonBsdf(sample, eval, pdf, wi, check);
  // The indices of refraction on either side (bsdf_model.h): reciprocity across a refraction
  // and where a transmission lobe peaks.
  for (auto [key, index] : {std::pair{"exterior_index", &model.exteriorIndex},
                            std::pair{"interior_index", &model.interiorIndex}})
    if (kw.contains(key) && !kw[key].is_none()) {
      *index = kw[key].cast<double>();
      if (!(*index > 0))
        throw py::value_error(fmt::format("{}: {} = {}: must be positive", check, key, *index));
    }
  return released([&] { return chi2::checkBsdf(model, wi, options); });
}

chi2::CheckResult checkWarp(const std::string& domain, py::object sample, py::object pdf,
                            const py::kwargs& kw) {
  const std::string check = checkName("check_warp", kw);
  requireKnown(kw, check, kCheckKeywords);
  chi2::CheckOptions options;
  readCheckOptions(kw, check, options);
  if (options.name.empty()) options.name = domain;
  const chi2::WarpModel model = pythonWarp(warpDomain(domain), sample, pdf, check);
  return released([&] { return chi2::checkWarp(model, options); });
}

}  // namespace

}  // namespace verity::python

PYBIND11_MODULE(verity, m) {
  namespace py = pybind11;
  using namespace verity::python;
  m.doc() =
      "Verity's statistical checks of BSDFs and warps written in NumPy (docs/python.md): "
      "check_bsdf, check_bsdf_family, check_stochastic_bsdf, check_warp; and compare, for two sets "
      "of renders as arrays "
      "or EXR files.";
  // The library's argument errors are the caller's: ValueError.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  bindCheckResult(m);
  bindCompare(m);
  bindFamily(m);
  bindStochastic(m);
  // What a pdf callable is given per call by the quadrature: at least this many points but
  // for a computation's last refinement levels, at most 2^18.
  m.attr("DENSITY_BATCH_POINTS") = verity::chi2::kDensityBatchPoints;
  m.def("check_bsdf", &checkBsdf, py::arg("sample"), py::arg("eval"), py::arg("pdf"),
        R"(Checks a BSDF given as three batched callables, for one incident direction wi:
    sample(wi, u) -> (wo, weight, pdf[, delta])  wi (3,), u (N, 3) in [0, 1): u[:, 0] picks
        the lobe, u[:, 1:] the direction; wo (N, 3), weight (N,) or (N, 3) = f*|cos|/pdf,
        pdf (N,) per unit solid angle (0: no sample), delta (N,) bool for delta lobes
    eval(wi, wo) -> (N,) or (N, 3)  f without the cosine; wi is (N, 3), row by row with wo,
        for the reciprocity check's reversed evaluations (reciprocity=False turns it off)
    pdf(wi, wo) -> (N,)
Local frame: normal +z, wi and wo pointing away from the surface, wo.z < 0 transmits.
Keywords: wi and alpha (required), name, samples, seed, resolution, power,
detect=(density_error, mass), max_samples, audited_samples, cells ('equal' or 'grid'),
threads (0: every core; 1: every callable on the calling thread), weight_tolerance,
reciprocity_tolerance, direction_rounding (4 float ulps: how far rounding may move a sampled
direction, to tell a failed comparison within rounding from one beyond), reciprocity, eta,
direction_tolerance,
expect={'reflection'|'refraction'|'pass-through': (share or None, albedo or None)},
exterior_index and interior_index (1: the indices of refraction above and below).
Returns a Result.)");
  m.def("check_warp", &checkWarp, py::arg("domain"), py::arg("sample"), py::arg("pdf"),
        R"(Checks a warp given as two batched callables on a domain ('square', 'disk',
'triangle' (barycentric b0, b1), 'hemisphere' or 'sphere'):
    sample(u) -> points  u (N, 2) in [0, 1); points (N, 2), or (N, 3) unit vectors on the
        hemisphere and sphere; a row of NaN declines
    pdf(points) -> (N,)  per unit area or solid angle
Keywords: alpha (required), name, samples, seed, resolution, power,
detect=(density_error, mass), max_samples, audited_samples, cells, threads. Returns a Result.)");
}
