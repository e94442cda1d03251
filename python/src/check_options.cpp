#include "check_options.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <stdexcept>

namespace verity::python {

const std::vector<std::string> kCheckKeywords = {
    "name",   "alpha",       "samples",         "seed",  "resolution", "power",
    "detect", "max_samples", "audited_samples", "cells", "threads"};
const std::vector<std::string> kStochasticKeywords = {"name",       "alpha", "samples", "seed",
                                                      "resolution", "power", "strata",  "threads"};
const std::vector<std::string> kBsdfKeywords = {"weight_tolerance",
                                                "reciprocity_tolerance",
                                                "direction_rounding",
                                                "reciprocity",
                                                "eta",
                                                "direction_tolerance",
                                                "expect"};

namespace {

template <class T>
bool read(const py::kwargs& kw, const char* key, T& out) {
  if (!kw.contains(key) || kw[key].is_none()) return false;
  try {
    out = kw[key].cast<T>();
  } catch (const py::cast_error&) {
    throw py::type_error(fmt::format("keyword argument {} = {}: {}", key,
                                     py::repr(kw[key]).cast<std::string>(), py::type_id<T>()));
  }
  return true;
}

}  // namespace

void requireKnown(const py::kwargs& kw, const std::string& check,
                  const std::vector<std::string>& known) {
  for (const auto& item : kw) {
    const std::string key = py::str(item.first);
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw py::type_error(fmt::format("{}: unknown keyword argument '{}' (known: {})", check, key,
                                       fmt::join(known, ", ")));
  }
}

std::string checkName(const char* function, const py::kwargs& kw) {
  return kw.contains("name") && !kw["name"].is_none()
             ? fmt::format("{} '{}'", function, kw["name"].cast<std::string>())
             : function;
}

Eigen::Vector3d readWi(const py::kwargs& kw, const std::string& check) {
  if (!kw.contains("wi"))
    throw py::type_error(check +
                         ": the keyword argument wi (the incident direction, (x, y, z) in "
                         "the local frame, normal +z) is required");
  const auto values = kw["wi"].cast<std::vector<double>>();
  if (values.size() != 3 || !(Eigen::Vector3d(values.data()).norm() > 0))
    throw py::value_error(check + ": wi must be a non-zero direction of 3 numbers");
  return Eigen::Vector3d(values.data());
}

void readCheckOptions(const py::kwargs& kw, const std::string& check, chi2::CheckOptions& o) {
  read(kw, "name", o.name);
  if (!read(kw, "alpha", o.significance))
    throw py::type_error(fmt::format(
        "{}: the keyword argument alpha (the per-test significance level, e.g. 0.01) is "
        "required",
        check));
  if (!(o.significance > 0 && o.significance < 1))
    throw py::value_error(fmt::format("{}: alpha = {}: must be in (0, 1)", check, o.significance));
  read(kw, "samples", o.samples);
  uint64_t seed = 0;
  if (read(kw, "seed", seed)) o.seed = seed;
  read(kw, "resolution", o.resolution);
  if (o.resolution < 0)
    throw py::value_error(
        fmt::format("{}: resolution = {}: must be 0 (the default) or more", check, o.resolution));
  read(kw, "power", o.power);
  std::pair<double, double> detect;
  if (read(kw, "detect", detect)) {
    chi2::DetectionTarget t;
    t.densityError = detect.first;
    t.mass = detect.second;
    t.power = o.power;
    o.detect = t;
  }
  read(kw, "max_samples", o.maxSamples);
  read(kw, "threads", o.threads);
  if (o.threads < 0)
    throw py::value_error(
        fmt::format("{}: threads = {}: must be 0 (every core) or more", check, o.threads));
  long long audited = 0;
  if (read(kw, "audited_samples", audited)) {
    if (audited < 1)
      throw py::value_error(
          fmt::format("{}: audited_samples = {}: must be at least 1", check, audited));
    o.auditedSamples = audited;
  }
  std::string cells;
  if (read(kw, "cells", cells)) {
    try {
      o.cells = chi2::parseCellLayout(cells, "cells");
    } catch (const std::invalid_argument& e) {
      throw py::value_error(fmt::format("{}: {}", check, e.what()));
    }
  }
}

void readStochasticOptions(const py::kwargs& kw, const std::string& check,
                           chi2::StochasticCheckOptions& o) {
  readCheckOptions(kw, check, o);
  read(kw, "strata", o.strata);
  if (!(o.strata >= 2 && o.strata % 2 == 0))
    throw py::value_error(
        fmt::format("{}: strata = {}: must be even and at least 2", check, o.strata));
}

void readBsdfOptions(const py::kwargs& kw, const std::string& check, chi2::BsdfCheckOptions& o) {
  readCheckOptions(kw, check, o);
  readBsdfKeywords(kw, check, o);
}

void readBsdfKeywords(const py::kwargs& kw, const std::string& check, chi2::BsdfCheckOptions& o) {
  read(kw, "weight_tolerance", o.weightTolerance);
  read(kw, "reciprocity_tolerance", o.reciprocityTolerance);
  read(kw, "direction_rounding", o.directionRounding);
  read(kw, "reciprocity", o.checkReciprocity);
  double eta = 0;
  if (read(kw, "eta", eta)) o.delta.eta = eta;
  read(kw, "direction_tolerance", o.delta.directionTolerance);
  std::map<std::string, std::pair<std::optional<double>, std::optional<std::vector<double>>>>
      expect;
  if (!read(kw, "expect", expect)) return;
  for (const auto& [lobe, e] : expect) {
    int k = 0;
    while (k < static_cast<int>(chi2::DeltaLobe::Count) &&
           lobe != chi2::deltaLobeName(chi2::DeltaLobe(k)))
      ++k;
    if (k == static_cast<int>(chi2::DeltaLobe::Count))
      throw py::value_error(fmt::format(
          "{}: expect['{}']: the delta lobes are reflection, refraction and pass-through", check,
          lobe));
    chi2::DeltaExpectation& x = o.delta.expect(chi2::DeltaLobe(k));
    x.share = e.first;
    if (e.second)
      x.albedo = Eigen::Map<const Eigen::ArrayXd>(e.second->data(),
                                                  static_cast<Eigen::Index>(e.second->size()));
  }
}

}  // namespace verity::python
