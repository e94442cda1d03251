// `verity compare A.exr B.exr` or `verity compare -a A1.exr A2.exr ... -b B1.exr ...`: do two
// sides estimate the same image? A side is one image with variance channels (a Verity EXR
// rendered with --variance) or a set of independent renders from any renderer. Per-tile Welch
// t-tests decided by Holm's procedure (validation/image_comparison.h).
// With --margin M it also tests equivalence within M (validation/compare/round_decision.h).
// Exit status 0 when they agree (with --margin: are EQUIVALENT), 1 when they differ, 3 with
// --margin when they are neither, 2 on bad input. Runs in one process.
#pragma once

#include <CLI/CLI.hpp>

#include "distributed/process_group.h"

namespace verity {

void addCompareCommand(CLI::App& app, const ProcessGroup& group);

}  // namespace verity
