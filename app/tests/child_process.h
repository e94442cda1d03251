// Runs the `verity` program as a child process for tests of the command line.
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
// Runs to completion and collects stderr.
Outcome run(const std::vector<std::string>& args);

}  // namespace verity::testing
