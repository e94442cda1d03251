// `verity reference`: renders a scene's reference image with its variance and a JSON sidecar.
#pragma once

#include <CLI/CLI.hpp>

namespace verity {

void addReferenceCommand(CLI::App& app);

}  // namespace verity
