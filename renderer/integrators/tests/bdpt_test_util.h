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
#include <string>
#include <vector>

#include "integrators/integrator_settings.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

namespace verity::bdpt_test {

// Mean and standard error of a region's per-pass pixel sum, per channel.
struct RegionEstimate {
  Eigen::Array3d mean = Eigen::Array3d::Zero();
  Eigen::Array3d standardError = Eigen::Array3d::Zero();
  uint64_t invalidSamples = 0;
};

// `region(x, y)` gives each pixel's region in [0, regions) or −1 for none. Renders `passes`
// independent passes of one sample per pixel with seeds base, base + 1, ...
inline std::vector<RegionEstimate> estimateRegions(const std::string& sceneText,
                                                   const std::string& integrator, int maxBounces,
                                                   int passes, uint64_t seedBase, int regions,
                                                   const std::function<int(int, int)>& region) {
  SceneFile file = loadSceneText(sceneText, "/tmp/bdpt-test.json");
  IntegratorSettings settings = file.integrator;
  settings.type = integrator;
  settings.maxBounces = maxBounces;
  const auto estimator = makeIntegrator(settings);
  const Vector2i res = file.scene->camera().resolution();
  std::vector<Eigen::Array3d> sum(regions, Eigen::Array3d::Zero()),
      sumSquares(regions, Eigen::Array3d::Zero());
  std::vector<RegionEstimate> out(regions);
  for (int pass = 0; pass < passes; ++pass) {
    Film film(res);
    RenderOptions options;
    options.samplesPerPixel = 1;
    options.seed = seedBase + pass;
    file.sampler->setSeed(options.seed);
    const RenderStats stats = render(*file.scene, *estimator, *file.sampler, film, options);
    std::vector<Eigen::Array3d> passSum(regions, Eigen::Array3d::Zero());
    for (int y = 0; y < res.y(); ++y)
      for (int x = 0; x < res.x(); ++x)
        if (const int r = region(x, y); r >= 0) passSum[r] += film.mean(x, y).cast<double>();
    for (int r = 0; r < regions; ++r) {
      sum[r] += passSum[r];
      sumSquares[r] += passSum[r] * passSum[r];
      out[r].invalidSamples += stats.invalidSamples;
    }
  }
  for (int r = 0; r < regions; ++r) {
    out[r].mean = sum[r] / passes;
    const Eigen::Array3d variance =
        ((sumSquares[r] - sum[r] * out[r].mean) / (passes - 1)).max(0.0);
    out[r].standardError = (variance / passes).sqrt();
  }
  return out;
}

// Two-sided z quantile for family-wise level `alpha` over `tests` tests (Bonferroni).
inline double bonferroniZ(double alpha, int tests) {
  return boost::math::quantile(boost::math::normal(), 1 - alpha / (2 * tests));
}

// Expects equal means per channel: |a − b| ≤ z · √(se_a² + se_b²) (plus float rounding).
inline void expectSameMean(const RegionEstimate& a, const RegionEstimate& b, double z,
                           const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    const double se = std::hypot(a.standardError[c], b.standardError[c]);
    const double bound = z * se + 1e-6 * std::max(std::fabs(a.mean[c]), std::fabs(b.mean[c]));
    EXPECT_NEAR(a.mean[c], b.mean[c], bound)
        << what << ", channel " << c << " (z = " << (a.mean[c] - b.mean[c]) / se << ")";
  }
}

}  // namespace verity::bdpt_test
