// `verity bench`: raw Embree ray throughput on a scene's geometry against the path tracer's
// rays/s, single-threaded, the speedup at 2 threads, and peak memory.
#pragma once

#include <CLI/CLI.hpp>

namespace verity {

void addBenchCommand(CLI::App& app);

}  // namespace verity
