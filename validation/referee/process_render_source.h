// Renders by running each side's command template (command_template.h) as a process under
// /bin/sh, up to `jobs` at once, each with its own seed and output file in a work folder.
// A process is started with posix_spawn in a process group of its own, its stdout and stderr
// going to a log beside its output; a command that fails (non-zero exit, a signal, no output
// file or one that cannot be read) or runs past `renderTimeout` is an error that names the
// command, its side and seed, and shows the end of its log. Each EXR is read and deleted once
// rendered. A render is stopped, with every process of its group (SIGTERM, then SIGKILL after
// a second's grace), when it runs past its time, when the deadline passes, when another render
// of the round failed, or when the user interrupts: nothing is left running.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "validation/referee/render_source.h"

namespace verity::validation {

class ProcessRenderSource : public RenderSource {
 public:
  // templates[0] renders side A, templates[1] side B (either may be empty when never asked
  // for). `workDir` must exist and be writable.
  // renderTimeout: seconds one render may take (none: no limit).
  ProcessRenderSource(std::array<std::string, 2> templates, int jobs, std::filesystem::path workDir,
                      std::optional<int> spp, std::optional<double> renderTimeout = std::nullopt);

  std::vector<Rendered> render(const std::vector<RenderRequest>& requests,
                               RenderDeadline deadline) override;

 private:
  struct Stop;
  // Runs one request's command; throws VerityError when it fails or runs past its time,
  // RenderBudgetEnded when the deadline passes; returns nothing when `stop` ended it for
  // another reason (another render failed, the user interrupted).
  std::optional<Rendered> renderOne(const RenderRequest& request, const Stop& stop) const;

  std::array<std::string, 2> templates_;
  int jobs_;
  std::filesystem::path workDir_;
  std::optional<int> spp_;
  std::optional<double> renderTimeout_;
};

}  // namespace verity::validation
