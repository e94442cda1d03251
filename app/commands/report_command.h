// `verity report`: HTML and Markdown report with plots from study results (JSON Lines).
#pragma once

#include <CLI/CLI.hpp>

#include "distributed/process_group.h"

namespace verity {

// Runs in one process.
void addReportCommand(CLI::App& app, const ProcessGroup& group);

}  // namespace verity
