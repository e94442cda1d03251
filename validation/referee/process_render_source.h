// Renders by running each side's command template (command_template.h) as a process under
// /bin/sh, up to `jobs` at once, each with its own seed and output file in a work folder.
// A process is started with posix_spawn, its stdout and stderr going to a log beside its
// output; a command that fails (non-zero exit, a signal, or no output file) is an error that
// names the command and shows the end of its log. Each EXR is read and deleted once rendered.
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
  ProcessRenderSource(std::array<std::string, 2> templates, int jobs, std::filesystem::path workDir,
                      std::optional<int> spp);

  std::vector<Rendered> render(const std::vector<RenderRequest>& requests) override;

 private:
  // Runs one request's command; throws VerityError when it fails.
  Rendered renderOne(const RenderRequest& request) const;

  std::array<std::string, 2> templates_;
  int jobs_;
  std::filesystem::path workDir_;
  std::optional<int> spp_;
};

}  // namespace verity::validation
