// Calibration of the variance channels against independent renders. The variance of a pixel's
// mean that a render reports (variance / samples, from filmChannels, which fills the channels
// of `render --variance`) must match the spread of that mean over renders with different seeds
// when the samples are independent; with the correlated samplers (stratified, halton, sobol)
// it overstates that spread, which is why requireIndependentSamples refuses them.
//
// cornell-box at 16 pixels wide, 4 spp, three disjoint sets of renders, each render its own
// seed:
//  A (32 renders): a_p, the reported variance of pixel p's mean averaged over A, unbiased for
//    Var(mean_p) if the channels are right;
//  B (64 renders): b_p, the sample variance of pixel p's mean over B, unbiased for Var(mean_p)
//    whatever the sampler;
//  C (32 renders): weights w_p = 1 / (C's reported variance), independent of A and B, so that
//    E[w_p (a_p - b_p)] = 0 exactly when the channels are right, whatever the distribution of
//    the samples (no normality, no Jensen bias of a ratio of noisy variances).
// Over the P pixels with a positive weight (pixels are independent: each draws its own random
// numbers), the calibration ratio is rho = sum w a / sum w b, and z = mean(w (a - b)) / its
// standard error from the pixel-to-pixel spread is approximately standard normal by the
// central limit theorem over pixels. The variances are summed over R, G and B per pixel.
//
// One family of four checks at level 1%, Bonferroni: independent, two-sided, |z| <
// z(1 - 0.01 / 8); each correlated sampler, one-sided, z > z(1 - 0.01 / 4).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <iostream>

#include "core/error.h"
#include "film/image_io.h"
#include "loader/scene_loader.h"
#include "render/renderer.h"
#include "sampling/sampler.h"

namespace verity::variance_calibration_test {
namespace {

constexpr int kWidth = 16, kSpp = 4;
constexpr int kRendersA = 32, kRendersB = 64, kRendersC = 32;
constexpr double kFamilyLevel = 0.01;
constexpr int kChecks = 4;

// Per pixel, over a set of renders: the reported variance of the mean (summed over R, G, B)
// averaged over the renders, and the sample variance of the mean over the renders.
struct PixelVariances {
  std::vector<double> reported, observed;
};

PixelVariances renderSet(const SceneFile& file, const Integrator& integrator,
                         const Sampler& prototype, uint64_t firstSeed, int renders) {
  const Vector2i resolution = file.scene->camera().resolution();
  const size_t pixels = size_t(resolution.x()) * resolution.y();
  std::vector<double> reported(pixels), sum(3 * pixels), sumSquares(3 * pixels);
  auto sampler = prototype.clone();
  for (int r = 0; r < renders; ++r) {
    sampler->setSeed(firstSeed + r);
    Film film(resolution);
    RenderOptions options;
    options.samplesPerPixel = kSpp;
    render(*file.scene, integrator, *sampler, film, options);
    const ImageChannels image = filmChannels(film, true);
    const std::vector<float>& samples = image.planes.at("samples");
    int c = 0;
    for (const char* channel : {"R", "G", "B"}) {
      const std::vector<float>& mean = image.planes.at(channel);
      const std::vector<float>& variance = image.planes.at(std::string("variance.") + channel);
      for (size_t p = 0; p < pixels; ++p) {
        reported[p] += double(variance[p]) / samples[p] / renders;
        sum[c * pixels + p] += mean[p];
        sumSquares[c * pixels + p] += double(mean[p]) * mean[p];
      }
      ++c;
    }
  }
  PixelVariances out{reported, std::vector<double>(pixels)};
  for (size_t i = 0; i < sum.size(); ++i)
    out.observed[i % pixels] +=
        std::max(0.0, (sumSquares[i] - sum[i] * sum[i] / renders) / (renders - 1));
  return out;
}

struct Calibration {
  int pixels = 0;
  double ratio = 0, ratioStandardError = 0;
  double z = 0;  // of mean(w (a - b)) = 0
};

Calibration calibrate(const Sampler& prototype) {
  SceneFile file = loadScene(std::filesystem::path(VERITY_SOURCE_DIR) / "scenes/cornell-box.json",
                             SceneOverrides::atWidth(kWidth));
  const auto integrator = makeIntegrator(file.integrator);
  const PixelVariances a = renderSet(file, *integrator, prototype, 1000, kRendersA);
  const PixelVariances b = renderSet(file, *integrator, prototype, 2000, kRendersB);
  const PixelVariances c = renderSet(file, *integrator, prototype, 3000, kRendersC);
  std::vector<double> wa, wb;
  for (size_t p = 0; p < c.reported.size(); ++p)
    if (c.reported[p] > 0) {
      wa.push_back(a.reported[p] / c.reported[p]);
      wb.push_back(b.observed[p] / c.reported[p]);
    }
  Calibration out;
  out.pixels = static_cast<int>(wa.size());
  const double n = out.pixels;
  double meanA = 0, meanB = 0;
  for (int i = 0; i < out.pixels; ++i) meanA += wa[i] / n, meanB += wb[i] / n;
  out.ratio = meanA / meanB;
  double ssDifference = 0, ssLinearized = 0;
  for (int i = 0; i < out.pixels; ++i) {
    ssDifference += std::pow(wa[i] - wb[i] - (meanA - meanB), 2);
    ssLinearized += std::pow(wa[i] - out.ratio * wb[i], 2);  // delta method for the ratio
  }
  out.z = (meanA - meanB) / std::sqrt(ssDifference / (n - 1) / n);
  out.ratioStandardError = std::sqrt(ssLinearized / (n - 1) / n) / meanB;
  return out;
}

double normalQuantile(double p) {
  return boost::math::quantile(boost::math::normal(), p);
}

std::unique_ptr<Sampler> makeSamplerNamed(const std::string& name) {
  auto sampler = makeSampler(name, "sampler");
  sampler->setSamplesPerPixel(kSpp);
  return sampler;
}

// The ratio with its two-sided 99.75% interval (the independent check: tails of 0.01 / 8).
std::string describe(const std::string& sampler, const Calibration& cal) {
  return fmt::format(
      "{}: reported / observed variance of the pixel mean {:.4f} ± {:.4f} (99.75% CI, {} "
      "pixels), z = {:.2f}",
      sampler, cal.ratio, normalQuantile(1 - kFamilyLevel / kChecks / 2) * cal.ratioStandardError,
      cal.pixels, cal.z);
}

TEST(VarianceCalibration, IndependentSamplesReportTheVarianceOfTheMean) {
  const auto sampler = makeSamplerNamed("independent");
  EXPECT_NO_THROW(requireIndependentSamples(*sampler, "cornell-box.json", "the test"));
  const Calibration cal = calibrate(*sampler);
  std::cout << describe("independent", cal) << "\n";
  EXPECT_GE(cal.pixels, 200);
  EXPECT_LT(std::fabs(cal.z), normalQuantile(1 - kFamilyLevel / kChecks / 2))
      << describe("independent", cal);
}

TEST(VarianceCalibration, CorrelatedSamplersOverstateTheVarianceOfTheMeanAndAreRefused) {
  for (const char* name : {"stratified", "halton", "sobol"}) {
    const auto sampler = makeSamplerNamed(name);
    EXPECT_THROW(requireIndependentSamples(*sampler, "cornell-box.json", "the test"), VerityError)
        << name;
    const Calibration cal = calibrate(*sampler);
    std::cout << describe(name, cal) << "\n";
    EXPECT_GT(cal.z, normalQuantile(1 - kFamilyLevel / kChecks)) << describe(name, cal);
  }
}

}  // namespace
}  // namespace verity::variance_calibration_test
