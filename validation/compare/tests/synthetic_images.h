// Synthetic image pairs drawn from known distributions, for testing the comparison.
#pragma once

#include <functional>
#include <random>

#include "film/film.h"
#include "film/image_io.h"
#include "validation/compare/exr_statistics.h"

namespace verity::validation::testing {

// Expected value of channel c at pixel (x, y): a smooth colour gradient, never zero.
inline double expectedValue(int x, int y, int c, int width, int height) {
  const double colour[3] = {1.0, 0.6, 0.3};
  return colour[c] * (0.5 + double(x) / width + 0.5 * double(y) / height);
}

// Renders through the Film (so that the variance and count planes are the ones `verity
// render --variance` writes): `spp` samples per pixel, each channel the expected value times
// one Exp(1) variable shared by the three channels (skewed like Monte Carlo samples, and
// channels fully correlated, as in a grey scene), all times `scale`.
inline PixelStatistics exponentialImage(int width, int height, int spp, double scale, uint64_t seed,
                                        const std::string& label = "synthetic") {
  std::mt19937_64 rng(seed);
  std::exponential_distribution<double> exp1(1.0);
  Film film(Vector2i(width, height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int s = 0; s < spp; ++s) {
        const double e = exp1(rng) * scale;
        Color3 v;
        for (int c = 0; c < 3; ++c) v[c] = float(expectedValue(x, y, c, width, height) * e);
        film.addSample(x, y, v);
      }
  return pixelStatistics(filmChannels(film, true), label);
}

// Normal samples with relative standard deviation `relSigma`, drawn through their exact
// sufficient statistics: the mean is N(μ, σ²/n) and (n − 1)s²/σ² is χ²(n − 1), independent.
// The standardised draws are shared by the three channels (fully correlated channels).
inline PixelStatistics normalImage(int width, int height, int spp, double relSigma, double scale,
                                   std::mt19937_64& rng, const std::string& label = "synthetic") {
  std::normal_distribution<double> normal;
  std::chi_squared_distribution<double> chi2(spp - 1);
  PixelStatistics s;
  s.label = label;
  s.width = width;
  s.height = height;
  const size_t n = size_t(width) * height;
  for (int c = 0; c < 3; ++c) {
    s.mean[c].resize(n);
    s.variance[c].resize(n);
  }
  s.samples.assign(n, spp);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double z = normal(rng), q = chi2(rng) / (spp - 1);
      for (int c = 0; c < 3; ++c) {
        const double mu = expectedValue(x, y, c, width, height) * scale;
        const double sigma = relSigma * mu;
        s.mean[c][s.index(x, y)] = mu + sigma / std::sqrt(double(spp)) * z;
        s.variance[c][s.index(x, y)] = sigma * sigma * q;
      }
    }
  return s;
}

}  // namespace verity::validation::testing
