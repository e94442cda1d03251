// `verity report`: HTML and Markdown report with plots from study results (JSON Lines).
#pragma once

#include <CLI/CLI.hpp>

namespace verity {

void addReportCommand(CLI::App& app);

}  // namespace verity
