// The keyword arguments of check_bsdf and check_warp, read into the C++ checks' options
// (check_result.h, bsdf_adapter.h): one keyword per option, the C++ defaults as defaults.
#pragma once

#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/stochastic_check.h>

#include "callback.h"

namespace verity::python {

// Options every check takes: name, alpha (the per-test level, required), samples, seed,
// resolution, power, detect ((density error, mass)), max_samples, cells ("equal" or "grid")
// and threads (0: every core; 1: the callables on the calling thread alone). ValueError naming
// the keyword for a value out of range.
void readCheckOptions(const py::kwargs& kw, const std::string& check, chi2::CheckOptions& o);

// check_bsdf's own: weight_tolerance, reciprocity_tolerance, reciprocity (bool), eta and
// direction_tolerance of the delta lobes, and expect = {"reflection": (share, albedo), ...}
// (either may be None).
void readBsdfOptions(const py::kwargs& kw, const std::string& check, chi2::BsdfCheckOptions& o);
// Those alone (kBsdfKeywords), over what `o` holds: a family's options for one configuration.
void readBsdfKeywords(const py::kwargs& kw, const std::string& check, chi2::BsdfCheckOptions& o);

// check_stochastic_bsdf's: name, alpha, samples, seed, resolution and power as above, and
// strata (each cell's eval at strata × strata directions; even).
void readStochasticOptions(const py::kwargs& kw, const std::string& check,
                           chi2::StochasticCheckOptions& o);

// "check_bsdf 'NAME'" for the keyword name, else the function's name: how messages name a check.
std::string checkName(const char* function, const py::kwargs& kw);

// The required keyword wi, a non-zero direction of 3 numbers (TypeError or ValueError naming it).
Eigen::Vector3d readWi(const py::kwargs& kw, const std::string& check);

// TypeError naming any keyword in kw that is not in `known`.
void requireKnown(const py::kwargs& kw, const std::string& check,
                  const std::vector<std::string>& known);

// The keywords each reads.
extern const std::vector<std::string> kCheckKeywords, kBsdfKeywords, kStochasticKeywords;

}  // namespace verity::python
