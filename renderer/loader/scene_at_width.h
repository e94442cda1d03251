// A scene loaded at another image width, its aspect ratio kept: the camera's resolution is
// rewritten before the scene is built, so the image is the whole picture and relative paths
// (meshes, textures) still resolve against the scene file.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "loader/scene_loader.h"

namespace verity {

// Loads `file`; with width > 0 the camera renders width × (width · h / w) pixels.
SceneFile loadSceneAtWidth(const std::filesystem::path& file, int width);
// The scene's JSON with the camera's resolution rewritten that way, or nullopt when the file
// is not JSON or its resolution is malformed (the loader then reports the problem in its own
// words); throws VerityError when it cannot be read.
std::optional<nlohmann::json> sceneJsonAtWidth(const std::filesystem::path& file, int width);

}  // namespace verity
