#include "cli/threads_option.h"

#include "cli/number_options.h"

namespace verity {

namespace {
constexpr const char* kAllCores = "0: all cores";
}  // namespace

CLI::Option* addThreadsOption(CLI::App* cmd, int& threads, MpiUse use, const std::string& whose) {
  const bool perProcess = use == MpiUse::SplitsWork;
  const std::string help =
      std::string("Worker threads") + (whose.empty() ? "" : " " + whose) +
      (perProcess ? " per process" : "") + "; " + kAllCores +
      (perProcess ? " (under mpirun, the host's cores shared among its ranks)" : "");
  return cmd->add_option("--threads", threads, help)->check(wholeNumber(0));
}

CLI::Option* addThreadCountsOption(CLI::App* cmd, std::vector<int>& counts, int min) {
  const std::string help = std::string("Thread counts, comma-separated") +
                           (min == 0 ? std::string("; ") + kAllCores : "");
  return cmd->add_option("--threads", counts, help)->delimiter(',')->check(wholeNumber(min));
}

}  // namespace verity
