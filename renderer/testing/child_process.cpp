#include "testing/child_process.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace verity::testing {

pid_t spawn(const std::vector<std::string>& args, const std::string& stderrFile) {
  const pid_t pid = fork();
  if (pid == 0) {
    if (!stderrFile.empty()) {
      const int fd = open(stderrFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd >= 0) dup2(fd, STDERR_FILENO);
    }
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

int waitExit(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

Outcome finish(pid_t pid, const std::string& stderrFile) {
  Outcome outcome;
  outcome.status = waitExit(pid);
  std::stringstream text;
  text << std::ifstream(stderrFile).rdbuf();
  outcome.stderrText = text.str();
  return outcome;
}

Outcome run(const std::vector<std::string>& args) {
  const std::string file = (std::filesystem::temp_directory_path() /
                            ("verity_stderr_" + std::to_string(getpid()) + ".txt"))
                               .string();
  Outcome outcome = finish(spawn(args, file), file);
  std::filesystem::remove(file);  // one per process: left behind, they pile up in the temp folder
  return outcome;
}

}  // namespace verity::testing
