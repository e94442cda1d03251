// `verity render`: renders a scene file to OpenEXR and/or PNG.
#pragma once

#include <CLI/CLI.hpp>

namespace verity {

void addRenderCommand(CLI::App& app);

}  // namespace verity
