#include "camera/camera.h"

#include <gtest/gtest.h>

namespace verity {
namespace {

TEST(Camera, PinholeLooksDownMinusZWithRowsDownwards) {
  const Camera camera(Transform(), Vector2i(200, 100), 90, 1, 0);
  const Ray center = camera.generateRay(Point2f(100, 50), Point2f(0.5f, 0.5f));
  EXPECT_TRUE(center.d.isApprox(Vector3f(0, 0, -1)));
  // Top edge of the image at 45° up (vfov 90), left edge at atan(2) (aspect 2).
  const Ray top = camera.generateRay(Point2f(100, 0), Point2f(0.5f, 0.5f));
  EXPECT_TRUE(top.d.isApprox(Vector3f(0, 1, -1).normalized(), 1e-6f));
  const Ray left = camera.generateRay(Point2f(0, 50), Point2f(0.5f, 0.5f));
  EXPECT_TRUE(left.d.isApprox(Vector3f(-2, 0, -1).normalized(), 1e-6f));
}

TEST(Camera, ThinLensRaysMeetOnTheFocusPlane) {
  const float focus = 3;
  const Camera camera(Transform(), Vector2i(64, 64), 40, focus, 0.2f);
  const Point2f film(10.3f, 50.7f);
  const Ray a = camera.generateRay(film, Point2f(0.1f, 0.2f));
  const Ray b = camera.generateRay(film, Point2f(0.9f, 0.6f));
  EXPECT_FALSE(a.o.isApprox(b.o));
  // Where each ray crosses z = −focus.
  const Point3f pa = a(-focus / a.d.z()), pb = b(-focus / b.d.z());
  EXPECT_TRUE(pa.isApprox(pb, 1e-5f));
  // And that point is where the pinhole ray through the same film point goes.
  const Camera pinhole(Transform(), Vector2i(64, 64), 40, focus, 0);
  const Ray c = pinhole.generateRay(film, Point2f(0.5f, 0.5f));
  EXPECT_TRUE(c(-focus / c.d.z()).isApprox(pa, 1e-5f));
}

}  // namespace
}  // namespace verity
