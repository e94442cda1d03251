// The `verity` program.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <new>

#include "chi2/chi2_command.h"
#include "commands/render_command.h"
#include "core/error.h"
#include "distributed/process_group.h"
#include "validation/compare_command.h"
#include "validation/studies/bench_command.h"
#include "validation/studies/reference_command.h"
#include "validation/studies/report_command.h"
#include "validation/studies/study_command.h"

namespace {

// Commands that do not split their work over MPI ranks refuse to run N times side by side.
void refuseUnderMpi(CLI::App& app, const verity::ProcessGroup& group) {
  for (CLI::App* command : app.get_subcommands({}))
    if (command->get_name() != "render" && command->get_name() != "reference" &&
        command->get_name() != "study")
      command->preparse_callback([command, &group](size_t) {
        if (group.distributed())
          throw verity::VerityError(
              "", "",
              fmt::format("`verity {}` runs in one process; only render, reference and "
                          "study split their work over MPI ranks",
                          command->get_name()));
      });
}

// An error ends the whole job under MPI: the other ranks would wait for this one forever.
int fail(const verity::ProcessGroup& group, const std::string& message) {
  if (group.distributed())
    fmt::print(stderr, "verity: error (rank {} of {} on {}): {}\n", group.rank(), group.size(),
               group.hostName(), message);
  else
    fmt::print(stderr, "verity: error: {}\n", message);
  if (group.distributed()) group.abort(1);
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  // MPI_Init only when mpirun or srun started this process.
  const verity::ProcessGroup group(argc, argv);
  CLI::App app{"Verity: a physically based renderer whose estimators are checked by statistics"};
  app.require_subcommand(1);
  verity::addRenderCommand(app, group);
  verity::addBenchCommand(app);
  verity::addCompareCommand(app);
  verity::addReferenceCommand(app, group);
  verity::addStudyCommand(app, group);
  verity::addReportCommand(app);
  verity::addChi2Command(app);
  refuseUnderMpi(app, group);
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {
    // A command's own exit status (130: interrupted), not an error.
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    if (code != 0 && group.distributed()) group.abort(code);
    return code;
  } catch (const verity::VerityError& e) {
    return fail(group, e.what());
  } catch (const std::bad_alloc&) {
    return fail(group, "out of memory (the scene or image is too large)");
  } catch (const std::exception& e) {
    return fail(group, e.what());
  }
  return 0;
}
