// The ray log records what a scene traces, in order, and only while it is set.
#include "scene/ray_log.h"

#include <gtest/gtest.h>

#include "loader/scene_loader.h"
#include "scene/scene.h"

namespace verity {
namespace {

SceneFile unitSphereScene() {
  return loadSceneText(
      R"({"camera": {"transform": {"from": [0,0,5], "at": [0,0,0], "up": [0,1,0]},
                     "vfov": 45, "resolution": [8, 8]},
          "materials": [{"name": "white", "type": "lambertian", "albedo": 0.5}],
          "surfaces": [{"type": "sphere", "radius": 1, "material": "white"}]})",
      "/tmp/ray_log.json");
}

TEST(RayLog, RecordsEveryQueryInOrderWithItsKind) {
  SceneFile f = unitSphereScene();
  RayLog log;
  f.scene->setRayLog(&log);
  SurfaceInteraction si;
  const Ray hit(Point3f(0, 0, 5), Vector3f(0, 0, -1));
  const Ray miss(Point3f(0, 3, 5), Vector3f(0, 0, -1), 7.0f);
  EXPECT_TRUE(f.scene->intersect(hit, si));
  EXPECT_FALSE(f.scene->occluded(miss));
  f.scene->setRayLog(nullptr);
  EXPECT_TRUE(f.scene->occluded(hit));  // not logged

  ASSERT_EQ(log.rays().size(), 2u);
  EXPECT_FALSE(log.rays()[0].shadow);
  EXPECT_EQ(log.rays()[0].ray.o, hit.o);
  EXPECT_EQ(log.rays()[0].ray.d, hit.d);
  EXPECT_TRUE(log.rays()[1].shadow);
  EXPECT_EQ(log.rays()[1].ray.o, miss.o);
  EXPECT_EQ(log.rays()[1].ray.tmax, 7.0f);
}

}  // namespace
}  // namespace verity
