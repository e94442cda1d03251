// Ray origins leave their surface past the point's error bound, to the side asked for.
#include "core/ray.h"

#include <gtest/gtest.h>

namespace verity {
namespace {

// Signed distance from the plane through p with normal n, in double precision.
double heightAbove(const Point3f& q, const Point3f& p, const Normal3f& n) {
  return (q.cast<double>() - p.cast<double>()).dot(n.cast<double>());
}

TEST(OffsetRayOrigin, ClearsTheErrorBoundOnTheSideOfTheDirection) {
  const Point3f p(3.5f, -120.25f, 0.75f);
  const Vector3f pError(1e-4f, 2e-4f, 3e-4f);
  const Normal3f n = Normal3f(1, 2, -2).normalized();
  const double bound = n.cwiseAbs().cast<double>().dot(pError.cast<double>());
  const Point3f up = offsetRayOrigin(p, pError, n, Vector3f(0.3f, 1, 0));
  const Point3f down = offsetRayOrigin(p, pError, n, Vector3f(0, -1, 0.5f));
  EXPECT_GE(heightAbove(up, p, n), bound);
  EXPECT_LE(heightAbove(down, p, n), -bound);
  // Not much further than the bound: a few floats at p's magnitude.
  EXPECT_LT(heightAbove(up, p, n), bound + 1e-4);
}

TEST(OffsetRayOrigin, AnExactPointStillLeavesItsPlane) {
  const Point3f p(2, 0, -1);
  const Point3f up = offsetRayOrigin(p, Vector3f::Zero(), Normal3f::UnitY(), Vector3f(1, 1, 0));
  const Point3f down = offsetRayOrigin(p, Vector3f::Zero(), Normal3f::UnitY(), Vector3f(0, -1, 0));
  EXPECT_GT(up.y(), 0.0f);
  EXPECT_LT(down.y(), 0.0f);
  EXPECT_EQ(up.x(), p.x());
  EXPECT_EQ(up.z(), p.z());
}

TEST(SpawnRayTo, EndsBeforeTheTargetOnTheFacingSides) {
  const Point3f from(0, 0, 0), to(0, 5, 0);
  const Vector3f error = Vector3f::Constant(1e-3f);
  const Ray ray = spawnRayTo(from, error, Normal3f::UnitY(), to, error, -Normal3f::UnitY());
  EXPECT_GT(ray.o.y(), 0.0f);
  EXPECT_LT(ray(ray.tmax).y(), to.y());
  EXPECT_GT(ray(ray.tmax).y(), to.y() - 0.01f);
}

}  // namespace
}  // namespace verity
