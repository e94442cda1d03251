// The `verity` command-line program.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <new>

#include "chi2/chi2_command.h"
#include "commands/render_command.h"
#include "core/error.h"
#include "validation/compare_command.h"
#include "validation/studies/bench_command.h"
#include "validation/studies/reference_command.h"
#include "validation/studies/report_command.h"
#include "validation/studies/study_command.h"

int main(int argc, char** argv) {
  CLI::App app{"Verity: a physically based renderer whose estimators are checked by statistics"};
  app.require_subcommand(1);
  verity::addRenderCommand(app);
  verity::addBenchCommand(app);
  verity::addCompareCommand(app);
  verity::addReferenceCommand(app);
  verity::addStudyCommand(app);
  verity::addReportCommand(app);
  verity::addChi2Command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const verity::VerityError& e) {
    fmt::print(stderr, "verity: error: {}\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "verity: error: out of memory (the scene or image is too large)\n");
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "verity: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
