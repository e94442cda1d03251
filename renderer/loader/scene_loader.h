// Reads a DIRT-format JSON scene (docs/scene-format.md) into a Scene and the render
// settings the file asks for.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "integrators/integrator_settings.h"
#include "sampling/sampler.h"
#include "scene/scene.h"

namespace verity {

struct SceneFile {
  std::string name;  // the file name without its extension
  std::unique_ptr<Scene> scene;
  std::unique_ptr<Sampler> sampler;  // samplesPerPixel() is the file's sample count
  IntegratorSettings integrator;
  // What the scene states but probably does not mean (an albedo above 1, a light emitting
  // nothing), once per material, each naming the file and JSON path; `verity render` prints
  // them, and with --strict refuses the scene.
  std::vector<VerityError> warnings;
};

// Throws VerityError naming the file, the JSON path and the problem.
SceneFile loadScene(const std::filesystem::path& file);
// The same for scene text, as if it were the file `file` (relative paths resolve against it).
SceneFile loadSceneText(const std::string& text, const std::filesystem::path& file);

}  // namespace verity
