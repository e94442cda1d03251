// Runs the `verity` program for the MPI tests, alone or under mpirun with what this machine
// and CI need, kept out of users' way: --allow-run-as-root only when run as root (CI),
// --oversubscribe (3 ranks on 2 cores) and --bind-to none (mpirun binds each of 2 ranks to
// one core by default, which would squeeze a rank's threads onto it). Open MPI 4.1's shared-
// memory transport needs no container settings here.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace verity::mpi_testing {

struct Outcome {
  int status = 0;  // exit status, or minus the signal that ended the process
  std::string stderrText;
};

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

// Starts `args` (args[0] is the program) with stderr to `stderrFile`.
inline pid_t spawn(const std::vector<std::string>& args, const std::string& stderrFile) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = open(stderrFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) dup2(fd, STDERR_FILENO);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

inline Outcome wait(pid_t pid, const std::string& stderrFile) {
  int status = 0;
  waitpid(pid, &status, 0);
  Outcome outcome;
  outcome.status = WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
  std::stringstream text;
  text << std::ifstream(stderrFile).rdbuf();
  outcome.stderrText = text.str();
  return outcome;
}

inline std::string stderrFile() {
  return (std::filesystem::temp_directory_path() /
          ("verity_mpi_stderr_" + std::to_string(getpid()) + ".txt"))
      .string();
}

// Runs to completion and collects stderr.
inline Outcome run(const std::vector<std::string>& args) {
  const std::string file = stderrFile();
  return wait(spawn(args, file), file);
}

}  // namespace verity::mpi_testing
