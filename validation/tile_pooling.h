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
// A pixel enters the tile only when it has at least `minSamples` (≥ 2, so that its variance
// exists) in BOTH images, so that both estimates cover the same pixels.
#pragma once

#include "validation/pixel_statistics.h"
#include "validation/stats/welch_t.h"

namespace verity::validation {

struct TileRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixels [x0, x1) × [y0, y1)
};

struct PooledTile {
  MeanEstimate a, b;
  int pixels = 0;    // pixels used
  int excluded = 0;  // pixels left out for having too few samples in either image
};

// Requires images of the same resolution and minSamples ≥ 2.
PooledTile poolTile(const PixelStatistics& a, const PixelStatistics& b, const TileRect& tile,
                    int channel, int minSamples);

}  // namespace verity::validation
