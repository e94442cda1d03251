// The camera's importance and its densities, as light tracing uses them: We integrates to
// one over the image (for every lens point), connecting a point to the lens finds the film
// position generateRay came from, and the densities agree with generateRay's sampling.
#include <gtest/gtest.h>

#include <random>

#include "camera/camera.h"
#include "core/frame.h"
#include "sampling/warp.h"

namespace verity {
namespace {

Transform lookAtTransform() {
  // A rotation and a translation: the camera at (1, 2, 3) looking along a tilted axis.
  const Eigen::AngleAxisf r(0.7f, Vector3f(1, 2, -0.5f).normalized());
  Matrix4f m = Matrix4f::Identity();
  m.topLeftCorner<3, 3>() = r.toRotationMatrix();
  m.topRightCorner<3, 1>() = Vector3f(1, 2, 3);
  return Transform(m);
}

class CameraImportance : public ::testing::TestWithParam<float> {};  // the lens radius

// ∫_lens ∫ We cos θ dω dA / lensArea… Monte Carlo over directions: uniform on the hemisphere
// in front of a lens point, E[We cos θ / p] must be 1 / lensArea (1 for a pinhole).
TEST_P(CameraImportance, IntegratesToOneOverTheImage) {
  const float lensRadius = GetParam();
  const Camera camera(lookAtTransform(), Vector2i(48, 30), 50, 4, lensRadius);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u01(0, 1);
  const Point3f lens = camera.toWorld().point(Point3f(0.3f * lensRadius, -0.2f * lensRadius, 0));
  const Vector3f axis = camera.toWorld().vector(Vector3f(0, 0, -1)).normalized();
  const Frame frame(axis);
  const int n = 400000;
  double sum = 0, sumSquares = 0;
  for (int i = 0; i < n; ++i) {
    const Vector3f local = warp::squareToUniformHemisphere(Point2f(u01(rng), u01(rng)));
    const Vector3f d = frame.toWorld(local);
    const double v =
        camera.importance(lens, d) * local.z() / warp::squareToUniformHemispherePdf(local);
    sum += v;
    sumSquares += v * v;
  }
  const double mean = sum / n, se = std::sqrt((sumSquares / n - mean * mean) / n);
  EXPECT_NEAR(mean * camera.lensArea(), 1.0, 5 * se * camera.lensArea());
}

TEST_P(CameraImportance, ConnectionFindsTheFilmPositionAndDensities) {
  const float lensRadius = GetParam();
  const Camera camera(lookAtTransform(), Vector2i(48, 30), 50, 4, lensRadius);
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u01(0, 1);
  for (int i = 0; i < 200; ++i) {
    const Point2f film(48 * u01(rng), 30 * u01(rng)), lens(u01(rng), u01(rng));
    const Ray ray = camera.generateRay(film, lens);
    const float distance = 0.5f + 10 * u01(rng);
    const Point3f p = ray(distance);
    const auto s = camera.sampleImportance(p, lens);
    ASSERT_TRUE(s) << i;
    EXPECT_TRUE(s->lensPoint.isApprox(ray.o, 1e-4f));
    EXPECT_NEAR(s->film.x(), film.x(), 2e-3f);
    EXPECT_NEAR(s->film.y(), film.y(), 2e-3f);
    EXPECT_NEAR(s->distance, distance, 1e-4f * distance);
    EXPECT_TRUE(s->wi.isApprox(-ray.d, 1e-4f));
    // Solid-angle density at p of the lens point, and generateRay's densities.
    const Vector3f axis = camera.toWorld().vector(Vector3f(0, 0, -1)).normalized();
    const float cosTheta = ray.d.dot(axis);
    EXPECT_NEAR(s->pdf, distance * distance / (cosTheta * camera.lensArea()), 1e-3f * s->pdf);
    float pdfPos = 0, pdfDir = 0;
    camera.pdfImportance(ray.o, ray.d, &pdfPos, &pdfDir);
    EXPECT_FLOAT_EQ(pdfPos, 1 / camera.lensArea());
    EXPECT_NEAR(pdfDir, 1 / (camera.imagePlaneArea() * std::pow(cosTheta, 3.0f)), 1e-4f * pdfDir);
    EXPECT_NEAR(s->importance,
                1 / (camera.imagePlaneArea() * camera.lensArea() * std::pow(cosTheta, 4.0f)),
                1e-4f * s->importance);
    Point2f landed;
    EXPECT_NEAR(camera.importance(ray.o, ray.d, &landed), s->importance, 1e-4f * s->importance);
    EXPECT_NEAR(landed.x(), film.x(), 2e-3f);
  }
  // Behind the camera, or outside the image: no connection.
  EXPECT_FALSE(
      camera.sampleImportance(camera.toWorld().point(Point3f(0, 0, 5)), Point2f(0.5f, 0.5f)));
  EXPECT_FALSE(
      camera.sampleImportance(camera.toWorld().point(Point3f(50, 0, -1)), Point2f(0.5f, 0.5f)));
}

INSTANTIATE_TEST_SUITE_P(Lenses, CameraImportance, ::testing::Values(0.0f, 0.25f));

}  // namespace
}  // namespace verity
