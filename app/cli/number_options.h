// Validators for the numeric options of the `verity` commands. They read the text as given,
// before CLI11 converts it, so that a fraction is refused where a count is expected (rather
// than rounded) and every range error says in words what the option takes:
// "--spp: must be a whole number of at least 1, not 0".
#pragma once

#include <CLI/CLI.hpp>
#include <climits>
#include <cmath>

#include "params/json_node.h"

namespace verity {

// A whole number from `min` to `max`.
CLI::Validator wholeNumber(long long min, long long max = INT_MAX);

// A number above `lo` (or from `lo`, when `loIncluded`) and below `hi` (or up to `hi`, when
// `hiIncluded`); `hi` infinite: no upper bound.
CLI::Validator realNumber(double lo, bool loIncluded, double hi = HUGE_VAL,
                          bool hiIncluded = false);

// The values a key of the scene format allows, for the option that overrides it: one
// statement of the range for both.
CLI::Validator wholeNumber(const IntRange& allowed);
CLI::Validator realNumber(const Range& allowed);

}  // namespace verity
