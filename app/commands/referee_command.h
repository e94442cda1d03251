// `verity referee --a "CMD" --b "CMD"`, `verity referee --baseline FILE --b "CMD"` or
// `verity referee --manifest FILE`: renders both sides (or the new side against a baseline) in
// rounds until they DIFFER or are EQUIVALENT within --margin, or the budget ends
// (validation/referee/referee.h; docs/referee.md). Exit status 0 EQUIVALENT, 1 DIFFER,
// 3 INCONCLUSIVE, 2 bad input (for a manifest: the worst of its entries, in the order 2, 1, 3).
#pragma once

#include <CLI/CLI.hpp>

#include "distributed/process_group.h"

namespace verity {

void addRefereeCommand(CLI::App& app, const ProcessGroup& group);

}  // namespace verity
