// Runs the `verity` program as a child process, for the tests of the command line and of
// mpirun (test support only: linked into test executables, never into the program).
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace verity::testing {

// Starts `args` (args[0] is the program); its stderr goes to `stderrFile` when given.
pid_t spawn(const std::vector<std::string>& args, const std::string& stderrFile = "");
// Waits for the child; its exit status, or minus the signal that ended it.
int waitExit(pid_t pid);

struct Outcome {
  int status = 0;
  std::string stderrText;
};
// Waits for a child started with its stderr going to `stderrFile`, and collects that.
Outcome finish(pid_t pid, const std::string& stderrFile);
// Runs to completion and collects stderr.
Outcome run(const std::vector<std::string>& args);

}  // namespace verity::testing
