// Rays leaving a surface never hit that surface again, at any scene scale, and hits land on
// the surface; small objects beside huge ones keep offsets of their own size.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "loader/scene_loader.h"
#include "sampling/independent_sampler.h"
#include "sampling/warp.h"

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

// A unit sphere resting on a floor two million units wide, beside a tilted unit triangle, under
// a light two units above the floor. Offsets that followed the scene's extent (1e6) rather
// than each point's own error lifted ray origins far above the light: the scene rendered black.
constexpr const char* kSphereOnHugeFloor = R"({
    "camera": {"transform": {"from": [0, 3, 6], "at": [0, 0.5, 0], "up": [0, 1, 0]}},
    "surfaces": [
      {"type": "quad", "size": 2e6, "material": {"type": "lambertian"},
       "transform": {"axis": [1, 0, 0], "angle": -90}},
      {"type": "sphere", "radius": 1, "material": {"type": "lambertian"},
       "transform": {"translate": [0, 1, 0]}},
      {"type": "triangle", "positions": [[1.5, 0.2, 0.5], [2.5, 0.3, 0.4], [2, 1.4, -0.3]],
       "material": {"type": "lambertian"}}
    ]})";

// Whether the segment a → b passes through the unit sphere at (0, 1, 0), in double precision;
// `margin` is how far from grazing it is.
bool segmentCrossesSphere(const Point3f& a, const Point3f& b, double* margin) {
  const Eigen::Vector3d o = a.cast<double>() - Eigen::Vector3d(0, 1, 0);
  const Eigen::Vector3d d = (b - a).cast<double>();
  const double t = std::clamp(-o.dot(d) / d.squaredNorm(), 0.0, 1.0);
  const double distance = (o + t * d).norm();
  *margin = std::fabs(distance - 1);
  return distance < 1;
}

TEST(IntersectionScale, SmallObjectsOnAHugeFloorKeepSmallOffsets) {
  SceneFile file = loadSceneText(kSphereOnHugeFloor, "/tmp/huge-floor.json");
  const Scene& scene = *file.scene;
  IndependentSampler sampler;
  sampler.startPixelSample(Point2i(0, 0), 0);
  int hits = 0, checkedShadowRays = 0;
  for (int i = 0; i < 20000; ++i) {
    // Rays from above towards the region around the sphere.
    const Point3f target(4 * sampler.next1D() - 2, 2 * sampler.next1D(), 4 * sampler.next1D() - 2);
    const Point3f from(8 * sampler.next1D() - 4, 6, 8 * sampler.next1D() - 4);
    const Ray ray(from, (target - from).normalized());
    SurfaceInteraction si;
    if (!scene.intersect(ray, si) || si.p.norm() > 4) continue;
    ++hits;
    const Ray leaving = si.spawnRay(si.ng);
    ASSERT_LT((leaving.o - si.p).norm(), 1e-5f) << "hit at " << si.p.transpose();
    SurfaceInteraction next;
    if (scene.intersect(leaving, next)) ASSERT_GT(next.t, 1e-3f);
    // A shadow ray to a point two units above the floor is blocked exactly when the segment
    // passes through the sphere (the triangle is left out of the comparison).
    const Point3f light(2 * sampler.next1D() - 1, 2.5f, 2 * sampler.next1D() - 1);
    if (light.y() < si.p.y() + 0.01f || si.ng.dot(light - si.p) <= 0) continue;
    // Leaving the (convex) sphere towards the light, the segment cannot enter it again.
    const bool onSphere = (si.p - Point3f(0, 1, 0)).norm() < 1.001f;
    double margin = 1;
    const bool crosses = !onSphere && segmentCrossesSphere(si.p, light, &margin);
    if (margin < 1e-3) continue;
    SurfaceInteraction blocker;
    const Ray shadow = si.spawnRayTo(light, Vector3f::Zero(), Normal3f::UnitY());
    const bool blocked = scene.intersect(shadow, blocker);
    if (blocked && blocker.shape != si.shape && blocker.p.x() > 1.4f) continue;  // the triangle
    ++checkedShadowRays;
    ASSERT_EQ(blocked, crosses) << "from " << si.p.transpose() << " to " << light.transpose();
  }
  EXPECT_GT(hits, 5000);
  EXPECT_GT(checkedShadowRays, 2000);
}

}  // namespace
}  // namespace verity
