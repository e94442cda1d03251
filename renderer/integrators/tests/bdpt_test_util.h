// Helpers of the bidirectional and light tracing tests: image-region estimates from
// independent one-sample passes, and their two-sample z-tests.
//
// Splatting integrators correlate the pixels of one pass (one light path lands on several
// pixels), so the variance of a sum of pixels is not the sum of the pixels' variances. Each
// pass here is rendered on its own (its own seed, so passes are independent) and the region
// sums of each pass are the samples; their sample variance is then valid for any
// integrator.
#pragma once

#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "integrators/integrator_settings.h"
#include "loader/scene_loader.h"
#include "render/component_images.h"
#include "render/renderer.h"

namespace verity::bdpt_test {

// Cornell box of side 555 with two spheres of materials `a` (left, back) and `b` (right,
// front), 32×32 pixels.
inline std::string cornellBox(const std::string& a, const std::string& b,
                              const std::string& extra) {
  return R"({
  "camera": {"transform": {"from": [0, 20, 1077.5], "at": [0, -4, 0], "up": [0, 1, 0]},
             "vfov": 40, "resolution": [32, 32]},
  "sampler": {"type": "independent"},)" +
         extra + R"(
  "materials": [
    {"name": "white", "type": "lambertian", "albedo": 0.73},
    {"name": "red", "type": "lambertian", "albedo": [0.65, 0.05, 0.05]},
    {"name": "green", "type": "lambertian", "albedo": [0.12, 0.45, 0.15]},
    {"name": "light", "type": "diffuse light", "emit": 15},
    {"name": "a", )" +
         a + R"(},
    {"name": "b", )" +
         b + R"(}
  ],
  "surfaces": [
    {"type": "quad", "size": 555, "material": "white",
     "transform": [{"axis": [1, 0, 0], "angle": -90}, {"translate": [0, -277.5, 0]}]},
    {"type": "quad", "size": 555, "material": "white",
     "transform": [{"axis": [1, 0, 0], "angle": 90}, {"translate": [0, 277.5, 0]}]},
    {"type": "quad", "size": 555, "material": "white", "transform": {"translate": [0, 0, -277.5]}},
    {"type": "quad", "size": 555, "material": "red",
     "transform": [{"axis": [0, 1, 0], "angle": 90}, {"translate": [-277.5, 0, 0]}]},
    {"type": "quad", "size": 555, "material": "green",
     "transform": [{"axis": [0, 1, 0], "angle": -90}, {"translate": [277.5, 0, 0]}]},
    {"type": "quad", "size": 130, "material": "light",
     "transform": [{"axis": [1, 0, 0], "angle": 90}, {"translate": [0, 277, 0]}]},
    {"type": "sphere", "radius": 100, "transform": {"translate": [-140, -177.5, -100]},
     "material": "a"},
    {"type": "sphere", "radius": 100, "transform": {"translate": [140, -177.5, 100]},
     "material": "b"}
  ]
})";
}

// The Cornell box with two Lambertian spheres: no delta vertex anywhere, so every strategy
// can sample every path.
inline std::string diffuseCornellBox() {
  return cornellBox(R"("type": "lambertian", "albedo": 0.5)",
                    R"("type": "lambertian", "albedo": 0.8)", "");
}

// Mean and standard error of a region's per-pass pixel sum, per channel.
struct RegionEstimate {
  Eigen::Array3d mean = Eigen::Array3d::Zero();
  Eigen::Array3d standardError = Eigen::Array3d::Zero();
  uint64_t invalidSamples = 0;
};

// Region estimates of the image (index 0) and, with a `layout`, of each of its components
// (index 1 + component). `region(x, y)` gives each pixel's region in [0, regions) or −1 for
// none. Renders `passes` independent passes of one sample per pixel with seeds base,
// base + 1, ...
inline std::vector<std::vector<RegionEstimate>> estimateImageRegions(
    const std::string& sceneText, const IntegratorSettings& settings,
    const std::optional<ComponentLayout::Kind>& layout, int passes, uint64_t seedBase, int regions,
    const std::function<int(int, int)>& region) {
  SceneFile file = loadSceneText(sceneText, "/tmp/bdpt-test.json");
  const auto estimator = makeIntegrator(settings);
  const Vector2i res = file.scene->camera().resolution();
  const int images = 1 + (layout ? ComponentLayout(*layout, settings.maxBounces).size() : 0);
  std::vector<std::vector<Eigen::Array3d>> sum(
      images, std::vector<Eigen::Array3d>(regions, Eigen::Array3d::Zero())),
      sumSquares = sum;
  std::vector<std::vector<RegionEstimate>> out(images, std::vector<RegionEstimate>(regions));
  for (int pass = 0; pass < passes; ++pass) {
    Film film(res);
    std::optional<ComponentImages> components;
    if (layout) components.emplace(ComponentLayout(*layout, settings.maxBounces), res);
    RenderOptions options;
    options.samplesPerPixel = 1;
    options.components = components ? &*components : nullptr;
    file.sampler->setSeed(seedBase + pass);
    const RenderStats stats = render(*file.scene, *estimator, *file.sampler, film, options);
    for (int i = 0; i < images; ++i) {
      const Film& f = i == 0 ? film : components->film(i - 1);
      std::vector<Eigen::Array3d> passSum(regions, Eigen::Array3d::Zero());
      for (int y = 0; y < res.y(); ++y)
        for (int x = 0; x < res.x(); ++x)
          if (const int r = region(x, y); r >= 0) passSum[r] += f.mean(x, y).cast<double>();
      for (int r = 0; r < regions; ++r) {
        sum[i][r] += passSum[r];
        sumSquares[i][r] += passSum[r] * passSum[r];
        out[i][r].invalidSamples += stats.invalidSamples;
      }
    }
  }
  for (int i = 0; i < images; ++i)
    for (int r = 0; r < regions; ++r) {
      RegionEstimate& e = out[i][r];
      e.mean = sum[i][r] / passes;
      const Eigen::Array3d variance =
          ((sumSquares[i][r] - sum[i][r] * e.mean) / (passes - 1)).max(0.0);
      e.standardError = (variance / passes).sqrt();
    }
  return out;
}

// Region estimates of the image of `integrator` alone (see estimateImageRegions).
inline std::vector<RegionEstimate> estimateRegions(const std::string& sceneText,
                                                   const std::string& integrator, int maxBounces,
                                                   int passes, uint64_t seedBase, int regions,
                                                   const std::function<int(int, int)>& region) {
  // The scene's settings (such as the MIS power) with the integrator and length asked for.
  IntegratorSettings settings = loadSceneText(sceneText, "/tmp/bdpt-test.json").integrator;
  settings.type = findIntegratorType(integrator);
  settings.maxBounces = maxBounces;
  return estimateImageRegions(sceneText, settings, std::nullopt, passes, seedBase, regions,
                              region)[0];
}

// Two-sided z quantile for family-wise level `alpha` over `tests` tests (Bonferroni).
inline double bonferroniZ(double alpha, int tests) {
  return boost::math::quantile(boost::math::normal(), 1 - alpha / (2 * tests));
}

// The z-score of a − b in channel c (float rounding allowed for: 0 when the means agree to
// it).
inline double zScore(const RegionEstimate& a, const RegionEstimate& b, int c) {
  const double difference = std::fabs(a.mean[c] - b.mean[c]);
  const double rounding = 1e-6 * std::max(std::fabs(a.mean[c]), std::fabs(b.mean[c]));
  if (difference <= rounding) return 0;
  return difference / std::hypot(a.standardError[c], b.standardError[c]);
}

// Whether the two-sided z-test at quantile `z` finds the means equal in every channel.
inline bool sameMean(const RegionEstimate& a, const RegionEstimate& b, double z) {
  for (int c = 0; c < 3; ++c)
    if (zScore(a, b, c) > z) return false;
  return true;
}

// Expects equal means per channel: |a − b| ≤ z · √(se_a² + se_b²) (plus float rounding).
inline void expectSameMean(const RegionEstimate& a, const RegionEstimate& b, double z,
                           const std::string& what) {
  for (int c = 0; c < 3; ++c)
    EXPECT_LE(zScore(a, b, c), z) << what << ", channel " << c << ": " << a.mean[c] << " vs "
                                  << b.mean[c];
}

}  // namespace verity::bdpt_test
