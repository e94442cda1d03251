#include "validation/studies/study_scene.h"

#include <algorithm>
#include <fstream>

#include "core/error.h"

namespace verity::studies {

std::optional<nlohmann::json> sceneJsonAtWidth(const std::filesystem::path& file, int width) {
  std::ifstream in(file);
  if (!in) throw VerityError(file.string(), "", "cannot open the scene file");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json scene;
  try {
    scene = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
  nlohmann::json& camera = scene["camera"];
  int w = 512, h = 512;  // the scene format's default resolution
  if (camera.contains("resolution") && camera["resolution"].is_array() &&
      camera["resolution"].size() == 2) {
    w = camera["resolution"][0].get<int>();
    h = camera["resolution"][1].get<int>();
  }
  const int height = std::max(1, int(std::lround(double(width) * h / std::max(w, 1))));
  camera["resolution"] = {width, height};
  return scene;
}

SceneFile loadStudyScene(const std::filesystem::path& file, int width) {
  if (width <= 0) return loadScene(file);
  const std::optional<nlohmann::json> scene = sceneJsonAtWidth(file, width);
  // A file that is not JSON: let the loader report the problem in its own words.
  return scene ? loadSceneText(scene->dump(), file) : loadScene(file);
}

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
  return overrideIntegrator(file.integrator, type, maxBounces, "--integrator");
}

}  // namespace verity::studies
