// `verity study convergence` and `verity study speedup`: many seeded renders, timed and
// compared against a reference, recorded as JSON Lines and summarised.
#pragma once

#include <CLI/CLI.hpp>

#include "distributed/process_group.h"

namespace verity {

// Under mpirun or srun, convergence and speed-up runs are dealt to the ranks of `group` and
// rank 0 writes the results; the strategies study runs in one process.
void addStudyCommand(CLI::App& app, const ProcessGroup& group);

}  // namespace verity
