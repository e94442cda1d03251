// Scenes for studies and validation suites: the shipped corpus and the integrator a study asks
// for (loader/scene_loader.h loads a scene with a command line's overrides).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "integrators/integrator_settings.h"
#include "loader/scene_loader.h"

namespace verity::studies {

// Every scene this project ships, sorted: scenes/*.json, scenes/stress/*.json and
// scenes/crosscheck/*.json under `scenesDir`.
std::vector<std::filesystem::path> shippedScenes(const std::filesystem::path& scenesDir);
// A shipped scene's name as the tests print it: "cornell-box", "stress/floor-40".
std::string shippedSceneName(const std::filesystem::path& file);

// The integrator settings of `file` with the type (any accepted spelling; "" keeps the scene's) and
// max bounces (if ≥ 0) overridden; throws VerityError for an unknown type.
IntegratorSettings studyIntegrator(const SceneFile& file, const std::string& type, int maxBounces);

}  // namespace verity::studies
