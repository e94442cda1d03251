#include "validation/studies/study_scene.h"

#include <algorithm>

namespace verity::studies {

std::vector<std::filesystem::path> shippedScenes(const std::filesystem::path& scenesDir) {
  std::vector<std::filesystem::path> scenes;
  for (const auto& folder : {scenesDir, scenesDir / "stress", scenesDir / "crosscheck"})
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.path().extension() == ".json") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

std::string shippedSceneName(const std::filesystem::path& file) {
  const std::string folder = file.parent_path().filename().string();
  const std::string name = file.stem().string();
  return folder == "stress" || folder == "crosscheck" ? folder + "/" + name : name;
}

IntegratorSettings studyIntegrator(const SceneFile& file, const std::string& type, int maxBounces) {
  return overrideIntegrator(file.integrator, integratorOverrides(type, maxBounces));
}

}  // namespace verity::studies
