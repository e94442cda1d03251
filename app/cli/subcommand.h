// Registers a `verity` command together with how it uses the processes of an MPI job, so that
// each command declares it where it is defined rather than in a list kept elsewhere.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "distributed/process_group.h"

namespace verity {

enum class MpiUse {
  SplitsWork,  // under mpirun or srun the ranks share the work and rank 0 writes the results
  OneProcess,  // refuses to start under mpirun: N copies would do the same work side by side
};

// Adds the command `name` to `parent`. A OneProcess command refuses to run in a distributed
// `group`, before it parses its options.
CLI::App* addSubcommand(CLI::App& parent, const std::string& name, const std::string& description,
                        MpiUse use, const ProcessGroup& group);

}  // namespace verity
