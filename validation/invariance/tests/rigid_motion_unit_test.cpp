// The moved scene is the scene moved: bounds, camera and solid textures follow the motion.
#include <gtest/gtest.h>

#include "loader/scene_loader.h"
#include "materials/material.h"
#include "validation/invariance/rigid_motion.h"

namespace verity::validation {
namespace {

const char* const kScene = R"({
  "camera": {"transform": {"from": [0, 1, 5], "at": [0, 1, 0], "up": [0, 1, 0]},
             "resolution": [8, 8]},
  "materials": [{"name": "floor", "type": "lambertian",
                 "albedo": {"type": "checker", "even": 1, "odd": 0, "scale": 2}}],
  "surfaces": [
    {"type": "quad", "size": 4, "material": "floor",
     "transform": [{"axis": [1, 0, 0], "angle": -90}, {"translate": [0, -0.9, 0]}]},
    {"type": "sphere", "radius": 0.5, "material": {"type": "lambertian", "albedo": 0.5},
     "transform": {"translate": [1, 0.5, -1]}}
  ]})";

SceneFile load(const nlohmann::json& scene) {
  return loadSceneText(scene.dump(), "/tmp/m.json");
}

TEST(RigidMotion, PlanesPutTheLowerBoundsAtTheOrigin) {
  const nlohmann::json scene = nlohmann::json::parse(kScene);
  const SceneFile original = load(scene);
  const std::vector<RigidMotion> motions = standardMotions(*original.scene);
  ASSERT_EQ(motions.size(), 5u);
  const SceneFile moved = load(moveScene(scene, motions.front()));
  EXPECT_NEAR(moved.scene->bounds().lo.norm(), 0, 1e-5);
  const Vector3f shift = -original.scene->bounds().lo;
  EXPECT_NEAR((moved.scene->bounds().hi - original.scene->bounds().hi - shift).norm(), 0, 1e-5);
}

// Small objects on a floor two million units wide: moved onto the planes or turned, they would
// sit where floats are 1/16 apart, so only the exact motions (turn90, mirror) remain.
TEST(RigidMotion, NoRoundingMotionForAScenesTooWideForItsSmallestSurface) {
  nlohmann::json scene = nlohmann::json::parse(kScene);
  scene["surfaces"].push_back({{"type", "quad"},
                               {"size", 2e6},
                               {"transform", {{"axis", {1, 0, 0}}, {"angle", -90}}},
                               {"material", scene["surfaces"][0]["material"]}});
  std::vector<std::string> names;
  for (const RigidMotion& m : standardMotions(*load(scene).scene)) names.push_back(m.name);
  EXPECT_EQ(names, (std::vector<std::string>{"turn90", "mirror"}));
}

TEST(RigidMotion, CameraRaysAndTexturesFollowEveryMotion) {
  const nlohmann::json scene = nlohmann::json::parse(kScene);
  const SceneFile original = load(scene);
  for (const RigidMotion& motion : standardMotions(*original.scene)) {
    const SceneFile moved = load(moveScene(scene, motion));
    const Eigen::Matrix4f m = motion.matrix.cast<float>();
    for (float x : {0.5f, 3.25f, 7.5f})
      for (float y : {0.5f, 6.75f}) {
        // A mirror image sees at pixel x what the original saw at the mirrored pixel.
        const Point2f film(motion.mirrors ? 8 - x : x, y);
        const Ray a = original.scene->camera().generateRay(Point2f(x, y), Point2f(0.5f, 0.5f));
        const Ray b = moved.scene->camera().generateRay(film, Point2f(0.5f, 0.5f));
        const Point3f movedOrigin = m.topLeftCorner<3, 3>() * a.o + m.topRightCorner<3, 1>();
        const float size = 1 + movedOrigin.norm();
        EXPECT_NEAR((b.o - movedOrigin).norm() / size, 0, 1e-5) << motion.name;
        EXPECT_NEAR((b.d - m.topLeftCorner<3, 3>() * a.d).norm(), 0, 1e-5) << motion.name;
        SurfaceInteraction hitA, hitB;
        ASSERT_EQ(original.scene->intersect(a, hitA), moved.scene->intersect(b, hitB));
        if (!original.scene->intersect(a, hitA)) continue;
        // The checker moved with the floor: the same albedo at the corresponding point.
        const Vector3f up = Vector3f::UnitZ();
        const Color3 albedoA =
            hitA.material->eval(hitA.textureQuery(), up, up, TransportMode::Radiance);
        const Color3 albedoB =
            hitB.material->eval(hitB.textureQuery(), up, up, TransportMode::Radiance);
        EXPECT_TRUE(albedoA.isApprox(albedoB)) << motion.name << " at " << x << ", " << y;
      }
  }
}

TEST(RigidMotion, AnImageBackgroundIsRefused) {
  nlohmann::json scene = nlohmann::json::parse(kScene);
  scene["background"] = {{"type", "image"}, {"filename", "sky.png"}};
  EXPECT_THROW(moveScene(scene, {"turn"}), VerityError);
}

}  // namespace
}  // namespace verity::validation
