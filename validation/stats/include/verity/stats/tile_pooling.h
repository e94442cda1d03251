// Pools the pixels of one tile into one estimate per image, so that a tile is tested once.
//
// Estimator. For the tile's P pixels i, with pixel mean m_i, unbiased one-sample variance
// s_i² and n_i samples, the tile's value is the mean of the pixel means
//     M = (1/P) Σ_i m_i,
// whose expectation is the average of the pixels' expectations, identical in two correct
// renders of one scene whatever their sample counts. Pixels are independent (each draws its
// own random numbers), so
//     Var(M) = (1/P²) Σ_i σ_i²/n_i   is estimated without bias by   V = (1/P²) Σ_i s_i²/n_i,
// a sum of independent scaled variance estimates with n_i − 1 degrees of freedom each, whose
// Satterthwaite (1946) denominator is Σ_i (s_i²/(n_i P²))² / (n_i − 1).
//
// Only the pixels a mask marks enter, so that the two sides of a comparison cover the same
// pixels: a pixel needs at least 2 samples (for its variance) in every image compared.
#pragma once

#include <verity/stats/pixel_statistics.h>
#include <verity/stats/welch_t.h>

#include <vector>

namespace verity::validation {

struct TileRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixels [x0, x1) × [y0, y1)

  int area() const { return (x1 - x0) * (y1 - y0); }
};

// The two estimates one tile's test compares.
struct PooledTile {
  MeanEstimate a, b;
  int pixels = 0;    // pixels used
  int excluded = 0;  // pixels of the tile left out (unusable in either image)
};

// 1 for every pixel with at least `minSamples` (≥ 2) samples, 0 otherwise; row-major.
std::vector<char> pixelsWithSamples(const PixelStatistics& s, int minSamples);

// The estimate of the tile's mean of `channel` over the pixels that `usable` (width·height,
// row-major) marks; `pixels` receives their number (the estimate is zero when it is 0).
// Every marked pixel must have at least 2 samples (std::invalid_argument otherwise).
MeanEstimate poolPixels(const PixelStatistics& s, const TileRect& tile, int channel,
                        const std::vector<char>& usable, int* pixels);

}  // namespace verity::validation
