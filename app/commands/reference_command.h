// `verity reference`: renders a scene's reference image with its variance and a JSON sidecar.
#pragma once

#include <CLI/CLI.hpp>

#include "distributed/process_group.h"

namespace verity {

// Under mpirun or srun the ranks of `group` share the passes; rank 0 writes.
void addReferenceCommand(CLI::App& app, const ProcessGroup& group);

}  // namespace verity
