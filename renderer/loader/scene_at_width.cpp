#include "loader/scene_at_width.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace verity {

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
  if (!scene.is_object() || (scene.contains("camera") && !scene["camera"].is_object()))
    return std::nullopt;
  nlohmann::json& camera = scene["camera"];
  int w = 512, h = 512;  // the scene format's default resolution
  if (camera.contains("resolution")) {
    const nlohmann::json& r = camera["resolution"];
    if (!r.is_array() || r.size() != 2 || !r[0].is_number_integer() || !r[1].is_number_integer())
      return std::nullopt;
    w = r[0].get<int>();
    h = r[1].get<int>();
  }
  const int height = std::max(1, int(std::lround(double(width) * h / std::max(w, 1))));
  camera["resolution"] = {width, height};
  return scene;
}

SceneFile loadSceneAtWidth(const std::filesystem::path& file, int width) {
  if (width <= 0) return loadScene(file);
  const std::optional<nlohmann::json> scene = sceneJsonAtWidth(file, width);
  return scene ? loadSceneText(scene->dump(), file) : loadScene(file);
}

}  // namespace verity
