#include "validation/referee/process_render_source.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <exception>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "core/error.h"
#include "render/interrupt.h"
#include "validation/referee/command_template.h"

extern char** environ;

namespace verity::validation {

namespace {

// The last `limit` characters of the file.
std::string logTail(const std::filesystem::path& file, size_t limit = 2000) {
  std::stringstream text;
  text << std::ifstream(file).rdbuf();
  std::string s = text.str();
  if (s.size() > limit) s = "..." + s.substr(s.size() - limit);
  return s.empty() ? "(no output)" : s;
}

// Runs `command` under /bin/sh with stdout and stderr to `log`; its wait status.
int runShell(const std::string& command, const std::filesystem::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
  pid_t pid = 0;
  const int error =
      posix_spawn(&pid, "/bin/sh", &actions, nullptr, const_cast<char* const*>(argv), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0)
    throw VerityError("", "", fmt::format("cannot start /bin/sh: {}", std::strerror(error)));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw VerityError("", "", "waitpid failed");
  return status;
}

}  // namespace

ProcessRenderSource::ProcessRenderSource(std::array<std::string, 2> templates, int jobs,
                                         std::filesystem::path workDir, std::optional<int> spp)
    : templates_(std::move(templates)), jobs_(jobs), workDir_(std::move(workDir)), spp_(spp) {
  if (jobs_ < 1) throw std::invalid_argument("ProcessRenderSource: jobs below 1");
}

Rendered ProcessRenderSource::renderOne(const RenderRequest& request) const {
  const int side = static_cast<int>(request.side);
  const std::string name = fmt::format("{}-{}", side == 0 ? "a" : "b", request.seed);
  const std::filesystem::path out = workDir_ / (name + ".exr"), log = workDir_ / (name + ".log");
  const std::string& text = templates_[side];
  if (text.empty()) throw std::logic_error("ProcessRenderSource: no command for this side");
  const std::string command = expandCommand(text, request.seed, out.string(), spp_);
  const int status = runShell(command, log);
  std::string failure;
  if (WIFSIGNALED(status))
    failure = fmt::format("was ended by signal {}", WTERMSIG(status));
  else if (WEXITSTATUS(status) != 0)
    failure = fmt::format("exited with status {}", WEXITSTATUS(status));
  else if (!std::filesystem::exists(out))
    failure = fmt::format("exited with status 0 but wrote no {}", out.string());
  if (!failure.empty())
    throw VerityError("", "",
                      fmt::format("the render command of side {} `{}` {}; its output:\n{}",
                                  side == 0 ? "A" : "B", command, failure, logTail(log)));
  Rendered r{readExr(out), out.string()};
  std::error_code ignored;
  std::filesystem::remove(out, ignored);
  std::filesystem::remove(log, ignored);
  return r;
}

std::vector<Rendered> ProcessRenderSource::render(const std::vector<RenderRequest>& requests) {
  std::vector<Rendered> out(requests.size());
  std::atomic<size_t> next{0};
  std::exception_ptr firstError;
  std::mutex errorMutex;
  // Each worker takes the next request until none is left, one has failed, or the user
  // interrupted (InterruptGuard: the renders in flight get the terminal's Ctrl-C themselves).
  auto worker = [&] {
    for (size_t i = next++; i < requests.size() && !InterruptGuard::flag(); i = next++) {
      {
        std::lock_guard lock(errorMutex);
        if (firstError) return;
      }
      try {
        out[i] = renderOne(requests[i]);
      } catch (...) {
        std::lock_guard lock(errorMutex);
        if (!firstError) firstError = std::current_exception();
      }
    }
  };
  std::vector<std::thread> workers;
  for (int j = 0; j < std::min<int>(jobs_, int(requests.size())); ++j) workers.emplace_back(worker);
  for (std::thread& t : workers) t.join();
  // Before a failure: a render ended by the same Ctrl-C fails too.
  if (InterruptGuard::flag())
    throw RendersInterrupted("interrupted before the round's renders were done");
  if (firstError) std::rethrow_exception(firstError);
  return out;
}

}  // namespace verity::validation
