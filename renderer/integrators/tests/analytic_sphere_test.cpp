// A Lambertian sphere of albedo a under a constant background L, seen from outside: being
// convex it sees only the background, so its radiance is exactly a·L, and every other pixel
// sees L. Each integrator must reproduce both to within a bound derived from the samples'
// own variance. The light tracer too: it sees the background directly through light subpaths
// that start on it (light_tracer.h).
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <boost/math/distributions/normal.hpp>
#include <string>

#include "integrators/integrator_registry.h"
#include "integrators/integrator_settings.h"
#include "loader/scene_loader.h"
#include "render/renderer.h"

namespace verity {
namespace {

constexpr float kAlbedo = 0.6f;
constexpr float kBackground = 1.5f;

const char* kScene = R"({
  "camera": {"transform": {"from": [0, 0, 4], "at": [0, 0, 0], "up": [0, 1, 0]}, "vfov": 40,
             "resolution": [24, 24]},
  "background": 1.5,
  "surfaces": [{"type": "sphere", "radius": 1, "material": {"type": "lambertian", "albedo": 0.6}}]
})";

// Pixels whose whole footprint is on the sphere (1) or off it (0); edge pixels (-1) mix both.
int coverage(const Camera& camera, const Scene& scene, int x, int y) {
  int hits = 0;
  for (int cy = 0; cy <= 1; ++cy)
    for (int cx = 0; cx <= 1; ++cx) {
      SurfaceInteraction si;
      hits += scene.intersect(camera.generateRay(Point2f(x + cx, y + cy), Point2f(0.5f, 0.5f)), si);
    }
  return hits == 4 ? 1 : hits == 0 ? 0 : -1;
}

class AnalyticSphere : public ::testing::TestWithParam<std::string> {};

TEST_P(AnalyticSphere, MatchesAlbedoTimesBackground) {
  SceneFile file = loadSceneText(kScene, "/tmp/analytic-sphere.json");
  IntegratorSettings settings = file.integrator;
  settings.type = findIntegratorType(GetParam());
  const auto integrator = makeIntegrator(settings);
  Film film(file.scene->camera().resolution());
  RenderOptions options;
  options.samplesPerPixel = 64;
  file.sampler->setSeed(7);
  render(*file.scene, *integrator, *file.sampler, film, options);

  // Pool pixels per region: mean of all samples and its standard error from the
  // samples' variance. Two regions × three channels × six integrators: a two-sided
  // z-test at family-wise level 1% with a Bonferroni correction over 36 tests. (Splatting
  // integrators correlate pixels within a pass; the sphere's pixels are bright wherever a
  // light path lands, so the pooled bound is only slightly optimistic there, and the test
  // of the light tracer's sphere in light_tracer_normalisation_test.cpp uses per-pass sums.)
  const double z = boost::math::quantile(boost::math::normal(), 1 - 0.01 / (2 * 36));
  for (int region = 0; region <= 1; ++region) {
    Eigen::Array3d sum = Eigen::Array3d::Zero(), var = Eigen::Array3d::Zero();
    double n = 0;
    int pixels = 0;
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < film.width(); ++x) {
        if (coverage(file.scene->camera(), *file.scene, x, y) != region) continue;
        const double c = film.count(x, y);
        sum += film.mean(x, y).cast<double>() * c;
        var += film.sampleVariance(x, y).cast<double>() * c;
        n += c;
        ++pixels;
      }
    ASSERT_GT(pixels, 20) << "region " << region;
    const Eigen::Array3d mean = sum / n;
    const double expected = region == 1 ? kAlbedo * kBackground : kBackground;
    for (int c = 0; c < 3; ++c) {
      // The path tracers' background region is exact (zero variance); allow float rounding.
      const double standardError = std::sqrt(var[c] / n / n);
      const double bound = z * standardError + 1e-6 * expected;
      EXPECT_NEAR(mean[c], expected, bound) << "region " << region << " channel " << c;
    }
  }
  EXPECT_EQ(film.invalidSamples(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Integrators, AnalyticSphere, ::testing::ValuesIn(radianceIntegrators()));

}  // namespace
}  // namespace verity
