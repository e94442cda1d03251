#include "core/program_files.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <sstream>

#include "core/error.h"

extern char** environ;

namespace verity {

std::filesystem::path sharedProgramFile(const std::string& name) {
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error)
    throw VerityError("/proc/self/exe", "",
                      "cannot tell where the running program is, to find " + name);
  const std::filesystem::path file =
      program.parent_path().parent_path() / "share" / "verity" / name;
  if (!std::filesystem::is_regular_file(file))
    throw VerityError(file.string(), "",
                      "missing: the program (" + program.string() + ") expects " + name +
                          " in share/verity beside its bin folder; reinstall it");
  return file;
}

std::filesystem::path findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::filesystem::path candidate =
        std::filesystem::path(dir.empty() ? "." : dir) / program;
    if (std::filesystem::is_regular_file(candidate) && access(candidate.c_str(), X_OK) == 0)
      return candidate;
  }
  return {};
}

std::filesystem::path findPythonWith(const std::string& module, const std::string& purpose) {
  std::vector<std::filesystem::path> candidates;
  if (const char* chosen = std::getenv("VERITY_PYTHON"); chosen && *chosen) {
    candidates.push_back(chosen);
  } else {
    if (const std::filesystem::path onPath = findOnPath("python3"); !onPath.empty())
      candidates.push_back(onPath);
    candidates.push_back("/usr/bin/python3");
  }
  std::string tried;
  for (const std::filesystem::path& python : candidates) {
    if (runProgram({python.string(), "-c", "import " + module}, /*quiet=*/true) == 0) return python;
    tried += (tried.empty() ? "" : ", ") + python.string();
  }
  throw VerityError("", "VERITY_PYTHON",
                    "cannot " + purpose + ": no Python that imports " + module + " (tried " +
                        tried + "; Debian: apt-get install python3-" + module +
                        ", or set VERITY_PYTHON)");
}

int runProgram(std::vector<std::string> args, bool quiet) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  }
  pid_t pid;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace verity
