// `verity render`: renders a scene file to OpenEXR and/or PNG.
#pragma once

#include <CLI/CLI.hpp>

#include "distributed/process_group.h"

namespace verity {

// Under mpirun or srun every rank of `group` renders its share of the passes and rank 0 alone
// writes the image (distributed/distributed_render.h).
void addRenderCommand(CLI::App& app, const ProcessGroup& group);

}  // namespace verity
