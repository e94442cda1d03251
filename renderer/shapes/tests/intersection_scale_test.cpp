// Rays leaving a surface never hit that surface again, at any scene scale, and hits land on
// the surface.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "sampling/independent_sampler.h"
#include "sampling/warp.h"
#include "scene/scene_loader.h"

namespace verity {
namespace {

// A unit scene (sphere, tilted quad, triangle mesh) scaled by `s` and moved away from the
// origin by `offset`·s, so both the magnitude and the relative precision vary.
std::string scaledScene(double s, double offset) {
  return fmt::format(R"({{
    "camera": {{"transform": {{"from": [0, 0, 10], "at": [0, 0, 0], "up": [0, 1, 0]}}}},
    "surfaces": [
      {{"type": "sphere", "radius": 1, "material": {{"type": "lambertian"}},
        "transform": [{{"translate": [{1}, 0, 0]}}, {{"scale": {0}}}]}},
      {{"type": "quad", "size": 2, "material": {{"type": "lambertian"}},
        "transform": [{{"axis": [1, 1, 0], "angle": 37}}, {{"translate": [{1}, 3, 0]}}, {{"scale": {0}}}]}},
      {{"type": "triangle", "positions": [[{2}, -3, -1], [{3}, -3, -1], [{1}, -2, 1.3]], "material": {{"type": "lambertian"}},
        "transform": {{"scale": {0}}}}}
    ]}})",
                     s, offset, offset - 1, offset + 1);
}

class IntersectionScale : public ::testing::TestWithParam<std::pair<double, double>> {};

TEST_P(IntersectionScale, NoSelfIntersection) {
  const auto [scale, offset] = GetParam();
  SceneFile file = loadSceneText(scaledScene(scale, offset), "/tmp/scale.json");
  const Scene& scene = *file.scene;
  IndependentSampler sampler;
  sampler.startPixelSample(Point2i(0, 0), 0);
  int hits = 0, selfHits = 0;
  const Point3f center = 0.5f * (scene.bounds().lo + scene.bounds().hi);
  const float extent = (scene.bounds().hi - scene.bounds().lo).norm();
  for (int i = 0; i < 20000; ++i) {
    // Rays from outside the scene towards it.
    const Vector3f dir = warp::squareToUniformSphere(sampler.next2D());
    const Point3f target = center + 0.3f * extent * warp::squareToUniformSphere(sampler.next2D());
    Ray ray(target - 2 * extent * dir, dir);
    SurfaceInteraction si;
    if (!scene.intersect(ray, si)) continue;
    ++hits;
    // Leave the surface on both sides (reflection and transmission directions).
    for (float side : {1.0f, -1.0f}) {
      Vector3f d = warp::squareToCosineHemisphere(sampler.next2D());
      d = Frame(side * si.ng).toWorld(d);
      SurfaceInteraction next;
      if (scene.intersect(si.spawnRay(d), next) && next.shape == si.shape) {
        // A sphere is hit again from inside (transmission), legitimately far away.
        const bool farSide = (next.p - si.p).norm() > 1e-3f * scale;
        if (!farSide) ++selfHits;
      }
    }
  }
  EXPECT_GT(hits, 1000);
  EXPECT_EQ(selfHits, 0) << "scale " << scale << " offset " << offset;
}

INSTANTIATE_TEST_SUITE_P(Scales, IntersectionScale,
                         ::testing::Values(std::make_pair(1e-4, 0.0), std::make_pair(1e-4, 50.0),
                                           std::make_pair(1.0, 0.0), std::make_pair(1.0, 100.0),
                                           std::make_pair(1e5, 0.0), std::make_pair(1e5, 30.0)));

}  // namespace
}  // namespace verity
