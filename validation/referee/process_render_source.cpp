#include "validation/referee/process_render_source.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <exception>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "core/error.h"
#include "render/interrupt.h"
#include "validation/referee/command_template.h"

extern char** environ;

namespace verity::validation {

namespace {

using Clock = std::chrono::steady_clock;

// The last `limit` characters of the file.
std::string logTail(const std::filesystem::path& file, size_t limit = 2000) {
  std::stringstream text;
  text << std::ifstream(file).rdbuf();
  std::string s = text.str();
  if (s.size() > limit) s = "..." + s.substr(s.size() - limit);
  return s.empty() ? "(no output)" : s;
}

// Why a command did not run to its end.
enum class Ended { Exited, TimedOut, Deadline, Cancelled };

// Starts `command` under /bin/sh, in a process group of its own, with stdout and stderr to
// `log`; its pid (the group's id).
pid_t startShell(const std::string& command, const std::filesystem::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
  pid_t pid = 0;
  const int error =
      posix_spawn(&pid, "/bin/sh", &actions, &attributes, const_cast<char* const*>(argv), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (error != 0)
    throw VerityError("", "", fmt::format("cannot start /bin/sh: {}", std::strerror(error)));
  return pid;
}

// The shell's wait status once it has exited, or nothing while it runs.
std::optional<int> exited(pid_t pid, bool block) {
  int status = 0;
  for (;;) {
    const pid_t r = waitpid(pid, &status, block ? 0 : WNOHANG);
    if (r == pid) return status;
    if (r == 0) return std::nullopt;
    if (errno != EINTR) throw VerityError("", "", "waitpid failed");
  }
}

// Ends the process group `pid` leads: SIGTERM, then SIGKILL after a grace period; the shell
// is reaped, and whatever of its group outlived it is killed.
void endGroup(pid_t pid) {
  kill(-pid, SIGTERM);
  const auto grace = Clock::now() + std::chrono::seconds(1);
  while (!exited(pid, false)) {
    if (Clock::now() >= grace) {
      kill(-pid, SIGKILL);
      exited(pid, true);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  kill(-pid, SIGKILL);  // a child that ignored SIGTERM after its shell ended
}

}  // namespace

// What ends a render before its command does.
struct ProcessRenderSource::Stop {
  RenderDeadline deadline;
  const std::atomic<bool>& cancelled;  // another render failed
};

ProcessRenderSource::ProcessRenderSource(std::array<std::string, 2> templates, int jobs,
                                         std::filesystem::path workDir, std::optional<int> spp,
                                         std::optional<double> renderTimeout)
    : templates_(std::move(templates)),
      jobs_(jobs),
      workDir_(std::move(workDir)),
      spp_(spp),
      renderTimeout_(renderTimeout) {
  if (jobs_ < 1) throw std::invalid_argument("ProcessRenderSource: jobs below 1");
  if (renderTimeout_ && !(*renderTimeout_ > 0))
    throw std::invalid_argument("ProcessRenderSource: a render timeout must be positive");
}

std::optional<Rendered> ProcessRenderSource::renderOne(const RenderRequest& request,
                                                       const Stop& stop) const {
  const int side = static_cast<int>(request.side);
  const std::string name = fmt::format("{}-{}", side == 0 ? "a" : "b", request.seed);
  const std::filesystem::path out = workDir_ / (name + ".exr"), log = workDir_ / (name + ".log");
  const std::string& text = templates_[side];
  if (text.empty()) throw std::logic_error("ProcessRenderSource: no command for this side");
  const std::string command = expandCommand(text, request.seed, out.string(), spp_);
  const std::string which = fmt::format("the render command of side {} (seed {}) `{}`",
                                        side == 0 ? "A" : "B", request.seed, command);
  const auto started = Clock::now();
  const pid_t pid = startShell(command, log);
  // Waits for the shell, polling what may stop it first.
  Ended ended = Ended::Exited;
  int status = 0;
  for (;;) {
    if (const std::optional<int> s = exited(pid, false)) {
      status = *s;
      break;
    }
    const auto now = Clock::now();
    if (renderTimeout_ && now - started >= std::chrono::duration<double>(*renderTimeout_))
      ended = Ended::TimedOut;
    else if (stop.deadline && now >= *stop.deadline)
      ended = Ended::Deadline;
    else if (stop.cancelled || InterruptGuard::flag())
      ended = Ended::Cancelled;
    if (ended != Ended::Exited) {
      endGroup(pid);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (ended == Ended::Cancelled) return std::nullopt;
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  if (ended == Ended::Deadline)
    throw RenderBudgetEnded(
        fmt::format("{} was stopped after {:.1f} s, with its process group", which, seconds));
  std::string failure;
  if (ended == Ended::TimedOut)
    failure = fmt::format(
        "ran past its limit of {} s per render (--render-timeout) and was killed, with its "
        "process group, after {:.1f} s",
        *renderTimeout_, seconds);
  else if (WIFSIGNALED(status))
    failure =
        fmt::format("was ended by signal {} ({})", WTERMSIG(status), strsignal(WTERMSIG(status)));
  else if (const int code = WEXITSTATUS(status); code > 128 && code < 128 + NSIG)
    // The shell's way of saying that the command it ran was ended by a signal.
    failure = fmt::format("exited with status {}: its command was ended by signal {} ({})", code,
                          code - 128, strsignal(code - 128));
  else if (code != 0)
    failure = fmt::format("exited with status {}", code);
  else if (!std::filesystem::exists(out))
    failure = fmt::format("exited with status 0 but wrote no {}", out.string());
  std::optional<Rendered> r;
  if (failure.empty()) {
    try {
      r = Rendered{readExr(out), out.string()};
    } catch (const std::exception& error) {
      failure = fmt::format("exited with status 0 but wrote an image that cannot be read: {}",
                            error.what());
    }
  }
  if (!failure.empty())
    throw VerityError("", "", fmt::format("{} {}; its output:\n{}", which, failure, logTail(log)));
  std::error_code ignored;
  std::filesystem::remove(out, ignored);
  std::filesystem::remove(log, ignored);
  return r;
}

std::vector<Rendered> ProcessRenderSource::render(const std::vector<RenderRequest>& requests,
                                                  RenderDeadline deadline) {
  std::vector<Rendered> out(requests.size());
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr firstError;
  std::mutex errorMutex;
  const Stop stop{deadline, failed};
  // Each worker takes the next request until none is left, one has failed (the renders in
  // flight are stopped), or the user interrupted (the renders, in groups of their own, do not
  // get the terminal's Ctrl-C: they are stopped).
  auto worker = [&] {
    for (size_t i = next++; i < requests.size() && !failed && !InterruptGuard::flag(); i = next++) {
      try {
        if (std::optional<Rendered> r = renderOne(requests[i], stop)) out[i] = std::move(*r);
      } catch (...) {
        std::lock_guard lock(errorMutex);
        if (!firstError) firstError = std::current_exception();
        failed = true;
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
