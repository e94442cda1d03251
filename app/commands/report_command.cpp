#include "commands/report_command.h"

#include <fmt/format.h>

#include "cli/exit_status.h"
#include "cli/output_paths.h"
#include "cli/subcommand.h"
#include "validation/studies/report.h"

namespace verity {

namespace {

struct ReportArgs {
  std::vector<std::string> inputs;
  std::string output;
};

}  // namespace

void addReportCommand(CLI::App& app, const ProcessGroup& group) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* cmd = addSubcommand(
      app, "report", "Write an HTML page and a Markdown summary with plots from study results",
      MpiUse::OneProcess, group);
  cmd->add_option("results", args->inputs, "Results files (.jsonl) of `verity study`")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->output,
                  "Report folder, e.g. reports/cornell-box/ (created if missing)")
      ->required();
  cmd->callback([args] {
    prepareOutputFolder(args->output, "-o");
    std::vector<std::filesystem::path> inputs(args->inputs.begin(), args->inputs.end());
    const int status = studies::makeReport(inputs, args->output);
    if (status != 0) {
      fmt::print(stderr, "verity: error: the report script failed (exit status {})\n", status);
      throw CLI::RuntimeError(kFailureStatus);
    }
    fmt::print(stderr, "wrote {}/index.html and summary.md\n", args->output);
  });
}

}  // namespace verity
