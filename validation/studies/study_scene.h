// Scenes for studies and validation suites: loaded at a chosen width, the shipped corpus, and
// the integrator a study asks for.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "integrators/integrator_settings.h"
#include "scene/scene_loader.h"

namespace verity::studies {

// Loads `file`; with width > 0 the camera renders width × (width · h / w) pixels (the
// scene's aspect ratio kept) by rewriting the camera's resolution before the scene is built.
SceneFile loadStudyScene(const std::filesystem::path& file, int width);
// The scene's JSON with the camera's resolution rewritten that way, or nullopt when the file
// is not JSON; throws VerityError when it cannot be read.
std::optional<nlohmann::json> sceneJsonAtWidth(const std::filesystem::path& file, int width);
// Every scene this project ships, sorted: scenes/*.json, scenes/stress/*.json and
// scenes/crosscheck/*.json under `scenesDir`.
std::vector<std::filesystem::path> shippedScenes(const std::filesystem::path& scenesDir);
// A shipped scene's name as the tests print it: "cornell-box", "stress/floor-40".
std::string shippedSceneName(const std::filesystem::path& file);

// The integrator settings of `file` with the type (any accepted spelling) and max bounces
// (if ≥ 0) overridden; throws VerityError for an unknown type.
IntegratorSettings studyIntegrator(const SceneFile& file, const std::string& type, int maxBounces);

}  // namespace verity::studies
