#include "validation/invariance/rigid_motion.h"

#include "core/error.h"

namespace verity::validation {

namespace {

nlohmann::json matrixTransform(const Eigen::Matrix4d& m) {
  nlohmann::json entries = nlohmann::json::array();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) entries.push_back(m(r, c));
  return {{"matrix", entries}};
}

// `transform` followed by `then` (the format applies an array's entries first to last).
nlohmann::json appended(const nlohmann::json* transform, const nlohmann::json& then) {
  nlohmann::json list = nlohmann::json::array();
  if (transform) {
    if (transform->is_array())
      list = *transform;
    else
      list.push_back(*transform);
  }
  list.push_back(then);
  return list;
}

void moveSolidTextures(nlohmann::json& node, const nlohmann::json& motion) {
  if (node.is_object()) {
    const auto type = node.find("type");
    if (type != node.end() && type->is_string() && (*type == "checker" || *type == "marble")) {
      const auto transform = node.find("transform");
      node["transform"] = appended(transform == node.end() ? nullptr : &*transform, motion);
    }
    for (auto& [key, child] : node.items()) moveSolidTextures(child, motion);
  } else if (node.is_array()) {
    for (auto& child : node) moveSolidTextures(child, motion);
  }
}

Eigen::Matrix4d translation(const Eigen::Vector3d& t) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topRightCorner<3, 1>() = t;
  return m;
}

Eigen::Matrix4d rotation(const Eigen::Matrix3d& r) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = r;
  return m;
}

}  // namespace

std::vector<RigidMotion> standardMotions(const Scene& scene) {
  const Bounds3f& bounds = scene.bounds();
  const Eigen::Vector3d lo = bounds.lo.cast<double>();
  const double extent = (bounds.hi - bounds.lo).cast<double>().norm();
  double smallest = kInfinity;
  for (const auto& shape : scene.shapes()) {
    const double size = (shape->bounds().hi - shape->bounds().lo).cast<double>().norm();
    if (size > 0) smallest = std::min(smallest, size);
  }
  // Coordinates up to `reach` round by 2^-23·reach at most: keep that below 1e-3 of the
  // smallest surface.
  const double reach = 1e-3 * smallest * 0x1p23;
  // "planes" brings every coordinate within the scene's extent of the origin, "turn" keeps them
  // within it: neither fits a scene wider than floats can place its smallest surface across.
  std::vector<RigidMotion> motions;
  if (extent <= reach) motions.push_back({"planes", translation(-lo)});
  const double far = std::min(100 * extent, reach - extent);
  if (far >= extent)
    motions.push_back({"far", translation(far * Eigen::Vector3d(0.48, -0.6, 0.64))});
  // 90° about y, then 90° about x, written exactly: (x, y, z) → (z, x, y).
  Eigen::Matrix3d turn90;
  turn90 << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  motions.push_back({"turn90", rotation(turn90)});
  if (extent <= reach)
    motions.push_back({"turn", rotation(Eigen::AngleAxisd(37 * EIGEN_PI / 180,
                                                          Eigen::Vector3d(1, 2, 3).normalized())
                                            .toRotationMatrix())});
  RigidMotion mirror{"mirror", Eigen::Matrix4d::Identity(), true};
  mirror.matrix(0, 0) = -1;
  motions.push_back(mirror);
  return motions;
}

nlohmann::json moveScene(nlohmann::json scene, const RigidMotion& motion) {
  const nlohmann::json transform = matrixTransform(motion.matrix);
  if (scene.contains("background") && scene["background"].is_object() &&
      scene["background"].value("type", "") == "image")
    throw VerityError("", "/background", "an image background cannot be moved with the scene");
  moveSolidTextures(scene, transform);
  nlohmann::json& camera = scene["camera"];
  const auto cameraTransform = camera.find("transform");
  nlohmann::json moved =
      appended(cameraTransform == camera.end() ? nullptr : &*cameraTransform, transform);
  if (motion.mirrors) moved.insert(moved.begin(), nlohmann::json::object({{"scale", {-1, 1, 1}}}));
  camera["transform"] = moved;
  nlohmann::json group = {{"type", "group"}, {"transform", transform}};
  group["children"] = scene.value("surfaces", nlohmann::json::array());
  scene["surfaces"] = nlohmann::json::array({group});
  return scene;
}

}  // namespace verity::validation
