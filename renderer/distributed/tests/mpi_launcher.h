// Runs the `verity` program for the MPI tests, alone or under mpirun with what this machine
// and CI need, kept out of users' way: --allow-run-as-root only when run as root (CI),
// --oversubscribe (3 ranks on 2 cores) and --bind-to none (mpirun binds each of 2 ranks to
// one core by default, which would squeeze a rank's threads onto it). Open MPI 4.1's shared-
// memory transport needs no container settings here.
#pragma once

#include <unistd.h>

#include <string>
#include <vector>

#include "testing/child_process.h"

namespace verity::mpi_testing {

using testing::finish;
using testing::Outcome;
using testing::run;
using testing::spawn;

// `program` under mpirun with `ranks` ranks; `environment` ("NAME=value") is exported to them.
inline std::vector<std::string> underMpirun(int ranks, const std::vector<std::string>& program,
                                            const std::vector<std::string>& environment = {}) {
  std::vector<std::string> args = {VERITY_MPIEXEC,    "-n",        std::to_string(ranks),
                                   "--oversubscribe", "--bind-to", "none"};
  if (getuid() == 0) args.push_back("--allow-run-as-root");
  for (const std::string& variable : environment) {
    args.push_back("-x");
    args.push_back(variable);
  }
  args.insert(args.end(), program.begin(), program.end());
  return args;
}

}  // namespace verity::mpi_testing
