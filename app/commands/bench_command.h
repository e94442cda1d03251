// `verity bench`: raw Embree ray throughput on a scene's geometry against the path tracer's
// rays/s, single-threaded, the speedup at 2 threads, and peak memory.
#pragma once

#include <CLI/CLI.hpp>

#include "distributed/process_group.h"

namespace verity {

// Runs in one process (it times one process's threads).
void addBenchCommand(CLI::App& app, const ProcessGroup& group);

}  // namespace verity
