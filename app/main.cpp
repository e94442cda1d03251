// The `verity` program.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <new>

#include "cli/exit_status.h"
#include "commands/bench_command.h"
#include "commands/chi2_command.h"
#include "commands/compare_command.h"
#include "commands/error_command.h"
#include "commands/referee_command.h"
#include "commands/reference_command.h"
#include "commands/render_command.h"
#include "commands/report_command.h"
#include "commands/study_command.h"
#include "core/error.h"
#include "core/version.h"
#include "distributed/process_group.h"

namespace {

void printError(const verity::ProcessGroup& group, const std::string& message) {
  if (group.distributed())
    fmt::print(stderr, "verity: error (rank {} of {} on {}): {}\n", group.rank(), group.size(),
               group.hostName(), message);
  else
    fmt::print(stderr, "verity: error: {}\n", message);
}

// An error ends the whole job under MPI: the other ranks would wait for this one forever.
int fail(const verity::ProcessGroup& group, const std::string& message, int status) {
  printError(group, message);
  if (group.distributed()) group.abort(status);
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  // MPI_Init only when mpirun or srun started this process.
  const verity::ProcessGroup group(argc, argv);
  CLI::App app{"Verity: a physically based renderer whose estimators are checked by statistics"};
  app.set_version_flag("--version",
                       fmt::format("verity {} (git {})", verity::kVersion, verity::kRevision));
  // Every command's --help shows its options' defaults; commands inherit this.
  app.option_defaults()->always_capture_default();
  app.require_subcommand(1);
  // CLI11's own errors (an unknown option, a missing value) read like every other error.
  app.failure_message([](const CLI::App* command, const CLI::Error& e) {
    return "verity: error: " + CLI::FailureMessage::simple(command, e);
  });
  // Each command declares where it is added whether it splits its work over MPI ranks.
  verity::addRenderCommand(app, group);
  verity::addBenchCommand(app, group);
  verity::addCompareCommand(app, group);
  verity::addRefereeCommand(app, group);
  verity::addErrorCommand(app, group);
  verity::addReferenceCommand(app, group);
  verity::addStudyCommand(app, group);
  verity::addReportCommand(app, group);
  verity::addChi2Command(app, group);
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {
    // A command's own exit status (130: interrupted), not an error.
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    const int shown = app.exit(e);  // prints the help, the version or the error
    const int code = shown == 0 ? 0 : verity::kBadInputStatus;
    if (code != 0 && group.distributed()) group.abort(code);
    return code;
  } catch (const verity::VerityError& e) {
    return fail(group, e.what(), verity::kBadInputStatus);
  } catch (const std::bad_alloc&) {
    return fail(group, "out of memory (the scene or image is too large)", verity::kFailureStatus);
  } catch (const std::exception& e) {
    return fail(group, e.what(), verity::kFailureStatus);
  }
  return 0;
}
