// Reads a DIRT-format JSON scene (docs/scene-format.md) into a Scene and the render
// settings the file asks for.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "integrators/integrator_registry.h"
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

// What a command line changes in a scene, applied to the parsed file before the scene is built;
// each field at its default keeps the file's value. Errors in them name the option.
struct SceneOverrides {
  // Image width in pixels (--resolution), the camera's aspect ratio kept: the camera itself
  // changes, so the image is the whole picture. 0: the file's.
  int width = 0;
  IntegratorOverrides integrator;  // --integrator, --max-bounces, --rr-depth
  // A sampler type with its keys at their defaults (--sampler), keeping the file's sample
  // count; "": the file's.
  std::string sampler;

  static SceneOverrides atWidth(int width) {
    SceneOverrides overrides;
    overrides.width = width;
    return overrides;
  }
};

// Throws VerityError naming the file, the JSON path (or the option) and the problem.
SceneFile loadScene(const std::filesystem::path& file, const SceneOverrides& overrides = {});
// The same for scene text, as if it were the file `file` (relative paths resolve against it).
SceneFile loadSceneText(const std::string& text, const std::filesystem::path& file,
                        const SceneOverrides& overrides = {});

}  // namespace verity
