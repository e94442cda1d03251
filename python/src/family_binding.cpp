#include "family_binding.h"

#include <fmt/format.h>
#include <pybind11/stl.h>
#include <verity/chi2/family_check.h>

#include <algorithm>
#include <map>
#include <optional>

#include "callback.h"
#include "check_options.h"
#include "python_bsdf.h"

namespace verity::python {

namespace {

// The keywords of check_bsdf_family beside the checks' own (kCheckKeywords, kBsdfKeywords):
// alpha is the family-wise level, and seed draws the interior points.
const std::vector<std::string> kFamilyKeywords = {"incidences", "from_below", "interior_points",
                                                  "stochastic"};

// "name=(lo, hi)" or "name=(lo, hi, 'log')", in the dict's order.
std::vector<chi2::FamilyParameter> readParameters(const py::dict& parameters,
                                                  const std::string& check) {
  std::vector<chi2::FamilyParameter> out;
  for (const auto& [key, value] : parameters) {
    chi2::FamilyParameter p;
    p.name = py::str(key);
    const auto range = value.cast<py::tuple>();
    const bool log = range.size() == 3 && py::str(range[2]).cast<std::string>() == "log";
    if (!(range.size() == 2 || log))
      throw py::value_error(fmt::format(
          "{}: parameters['{}'] = {}: give (lo, hi), or (lo, hi, 'log') for a range over decades",
          check, p.name, py::repr(value).cast<std::string>()));
    p.lo = range[0].cast<double>();
    p.hi = range[1].cast<double>();
    p.logarithmic = log;
    out.push_back(std::move(p));
  }
  return out;
}

// What a factory returned: its BSDF, and the keywords it states for that configuration's check.
struct Made {
  chi2::BsdfModel model;
  py::dict keywords;
};

// (sample, eval, pdf), (sample, eval, pdf, exterior_index, interior_index), or a dict of these
// names and any of check_bsdf's BSDF keywords (kBsdfKeywords); in the mean-weight mode also
// (sample, eval).
Made madeBsdf(const py::object& bsdf, bool stochastic, const std::string& at) {
  py::dict fields;
  if (py::isinstance<py::dict>(bsdf)) {
    fields = py::reinterpret_borrow<py::dict>(bsdf);
  } else if (py::isinstance<py::tuple>(bsdf) || py::isinstance<py::list>(bsdf)) {
    const py::tuple callables(bsdf);
    const bool pair = stochastic && callables.size() == 2;  // no pdf to give
    if (callables.size() == 3 || callables.size() == 5 || pair) {
      const char* names[] = {"sample", "eval", "pdf", "exterior_index", "interior_index"};
      for (size_t i = 0; i < callables.size(); ++i) fields[names[i]] = callables[i];
    }
  }
  if (!fields.contains("sample") || !fields.contains("eval") ||
      (!stochastic && !fields.contains("pdf")))
    throw py::type_error(fmt::format(
        "{}: the factory must return (sample, eval, pdf), (sample, eval, pdf, exterior_index, "
        "interior_index){} or a dict of these names and check_bsdf's BSDF keywords; it "
        "returned {}",
        at, stochastic ? ", (sample, eval)" : "", py::repr(bsdf).cast<std::string>()));
  Made m;
  m.model = pythonBsdf(fields["sample"], fields["eval"],
                       fields.contains("pdf") ? py::object(fields["pdf"]) : py::none(),
                       Eigen::Vector3d::UnitZ(), at);
  for (auto [key, index] : {std::pair{"exterior_index", &m.model.exteriorIndex},
                            std::pair{"interior_index", &m.model.interiorIndex}})
    if (fields.contains(key)) {
      *index = fields[key].cast<double>();
      if (!(*index > 0))
        throw py::value_error(fmt::format("{}: {} = {}: must be positive", at, key, *index));
    }
  std::vector<std::string> known = kBsdfKeywords;
  known.insert(known.end(), {"sample", "eval", "pdf", "exterior_index", "interior_index"});
  requireKnown(py::reinterpret_borrow<py::kwargs>(fields), at + ": the factory's dict", known);
  for (const auto& [key, value] : fields)
    if (std::find(kBsdfKeywords.begin(), kBsdfKeywords.end(), py::str(key).cast<std::string>()) !=
        kBsdfKeywords.end())
      m.keywords[key] = value;
  return m;
}

chi2::FamilyResult checkBsdfFamily(py::object factory, const py::dict& parameters,
                                   const py::kwargs& kw) {
  const std::string check = "check_bsdf_family";
  chi2::FamilyOptions options;
  options.stochastic = kw.contains("stochastic") && kw["stochastic"].cast<bool>();
  // The mean-weight mode takes check_stochastic_bsdf's keywords, the others check_bsdf's.
  std::vector<std::string> known = options.stochastic ? kStochasticKeywords : kCheckKeywords;
  if (!options.stochastic) known.insert(known.end(), kBsdfKeywords.begin(), kBsdfKeywords.end());
  known.insert(known.end(), kFamilyKeywords.begin(), kFamilyKeywords.end());
  known.erase(std::find(known.begin(), known.end(), "name"));
  requireKnown(kw, check, known);
  if (kw.contains("samples") && kw.contains("detect"))
    throw py::type_error(check +
                         ": samples and detect exclude each other (detect sizes each check)");
  std::optional<uint64_t> seed;
  if (options.stochastic) {
    readStochasticOptions(kw, check, options.stochasticCheck);
    options.level = options.stochasticCheck.significance;
    seed = options.stochasticCheck.seed;
    options.stochasticCheck.seed.reset();
  } else {
    readBsdfOptions(kw, check, options.check);
    // alpha is the family's level; each check's is its Šidák share, set by the family.
    options.level = options.check.significance;
    if (kw.contains("samples") && !kw.contains("detect")) options.check.detect.reset();
    seed = options.check.seed;
    options.check.seed.reset();  // each configuration's seed follows from its name
  }
  if (seed) options.seed = *seed;
  if (kw.contains("incidences")) options.incidences = kw["incidences"].cast<std::vector<double>>();
  if (kw.contains("from_below")) options.fromBelow = kw["from_below"].cast<bool>();
  if (kw.contains("interior_points")) options.interiorPoints = kw["interior_points"].cast<int>();
  const std::vector<chi2::FamilyParameter> box = readParameters(parameters, check);
  // The models the factory made, and the keywords it stated for each configuration's check,
  // dropped here with the GIL held: the family's own copies go without it, and must not be the
  // last owners of a Python reference.
  std::vector<chi2::BsdfModel> made;
  std::map<std::vector<double>, py::dict> stated;
  const chi2::BsdfFamily family = [&](const std::vector<double>& values) {
    py::gil_scoped_acquire gil;
    py::dict arguments;
    for (size_t i = 0; i < box.size(); ++i) arguments[py::str(box[i].name)] = values[i];
    const std::string at = fmt::format("{} at {}", check, py::repr(arguments).cast<std::string>());
    const Made m = madeBsdf(factory(**arguments), options.stochastic, at);
    if (options.stochastic && !m.keywords.empty())
      throw py::type_error(fmt::format(
          "{}: the factory stated {} for the check, which the mean-weight mode does not take", at,
          py::repr(m.keywords).cast<std::string>()));
    stated[values] = m.keywords;
    made.push_back(m.model);
    return m.model;
  };
  // Each configuration's keywords from the factory, over the family's: an `expect` that is
  // callable is called with the configuration's wi.
  options.configure = [&](const chi2::FamilyConfiguration& c, const chi2::BsdfModel&,
                          chi2::BsdfCheckOptions& o) {
    py::gil_scoped_acquire gil;
    const py::dict& keywords = stated.at(c.values);
    if (keywords.empty()) return;
    const std::string at = fmt::format("{} ({})", check, c.name);
    py::dict resolved;
    for (const auto& [key, value] : keywords) resolved[key] = value;
    if (resolved.contains("expect") && PyCallable_Check(resolved["expect"].ptr())) {
      const Eigen::Vector3d wi = c.wi();
      resolved["expect"] = call({resolved["expect"], at, "expect(wi)"},
                                py::make_tuple(py::make_tuple(wi.x(), wi.y(), wi.z())));
    }
    readBsdfKeywords(py::reinterpret_borrow<py::kwargs>(resolved), at, o);
  };
  // Validated before any call: a bad range or option is a ValueError at once.
  chi2::familyConfigurations(box, options);
  chi2::FamilyResult r;
  {
    py::gil_scoped_release release;
    r = chi2::checkBsdfFamily(family, box, options);
  }
  return r;
}

}  // namespace

void bindFamily(py::module_& m) {
  py::class_<chi2::FamilyResult>(m, "FamilyResult",
                                 "What a family check found; str() is its report, failures first.")
      .def_property_readonly(
          "verdict", [](const chi2::FamilyResult& r) { return chi2::verdictName(r.verdict()); },
          "'PASSED' (every configuration), 'FAILED' (any) or 'INCONCLUSIVE'")
      .def_property_readonly("passed", &chi2::FamilyResult::passed)
      .def_property_readonly(
          "configurations",
          [](const chi2::FamilyResult& r) {
            py::list out;
            for (size_t i = 0; i < r.configurations.size(); ++i) {
              const chi2::FamilyConfiguration& c = r.configurations[i];
              py::dict values;
              for (size_t k = 0; k < r.parameters.size(); ++k)
                values[py::str(r.parameters[k].name)] = c.values[k];
              py::dict d;
              d["name"] = c.name;
              d["values"] = values;
              d["corner"] = c.corner;
              d["incidence"] = c.incidence;
              d["below"] = c.below;
              d["result"] =
                  r.stochastic() ? py::cast(r.stochasticResults[i]) : py::cast(r.results[i]);
              out.append(d);
            }
            return out;
          },
          "each configuration in the family's order: name, values, corner, incidence (degrees), "
          "below, and its Result (a StochasticResult with stochastic=True)")
      .def_property_readonly("level", [](const chi2::FamilyResult& r) { return r.level; })
      .def_property_readonly("per_test_level",
                             [](const chi2::FamilyResult& r) { return r.perTestLevel; })
      .def("markdown", &chi2::FamilyResult::markdown)
      .def("json", &chi2::FamilyResult::json)
      .def("junit", &chi2::FamilyResult::junit, py::arg("suite") = "verity.check_bsdf_family",
           "JUnit XML for CI: one test case per configuration, FAILED a <failure>, "
           "INCONCLUSIVE an <error>")
      .def_property_readonly("report", &chi2::FamilyResult::report)
      .def("__str__", &chi2::FamilyResult::report)
      .def("__repr__", [](const chi2::FamilyResult& r) {
        return fmt::format("<verity.FamilyResult {}: {} configurations>",
                           chi2::verdictName(r.verdict()), r.configurations.size());
      });
  m.def("check_bsdf_family", &checkBsdfFamily, py::arg("factory"), py::arg("parameters"),
        R"(Checks a BSDF over its whole parameter space: every corner of the box of the
parameters' ranges and a stratified set of points inside it, each at every incidence.
    factory(**values) -> (sample, eval, pdf) or (sample, eval, pdf, exterior_index,
        interior_index): the three batched callables of check_bsdf for those values; or a
        dict of these names and check_bsdf's BSDF keywords for that configuration (expect,
        eta, ...; an expect that is callable is called with the configuration's wi)
    parameters: {name: (lo, hi)} or {name: (lo, hi, 'log')}, ends included (the values your
        loader accepts); 'log' spreads the interior points evenly in log(value)
Keywords: alpha (required: the family-wise level, split by Sidak over every test),
incidences (degrees, default [0, 30, 60, 85, 89.9, 90]), from_below (False),
interior_points (8), seed (of the interior points), detect (default (0.02, 0.25)) or samples,
and check_bsdf's other keywords but name and wi, for every configuration. With stochastic=True
each configuration gets check_stochastic_bsdf's mean-weight check instead (its keywords
samples, resolution, power and strata), and the factory may return (sample, eval).
Returns a FamilyResult.)");
}

}  // namespace verity::python
