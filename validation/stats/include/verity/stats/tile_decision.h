// Many tiles' Welch tests decided together, on plain per-tile estimates of two images (each a
// mean with its estimated variance and Satterthwaite denominator, however it was made: pooled
// pixels, tile_pooling.h, or the spread of independent renders):
// - each test: Welch's t-test (Welch 1947, welch_t.h), its z-score and the smallest relative
//   bias it detects with the given power at the Bonferroni level α/m (power.h); Holm's
//   procedure rejects at least what Bonferroni rejects, so that figure is an upper bound;
// - the family: Holm's step-down procedure (Holm 1979, holm.h) at family-wise level α over
//   every test; the images DIFFER when it rejects any;
// - diagnostics: Kolmogorov-Smirnov uniformity of each channel's p-values over the
//   non-deterministic tests (Bonferroni over the channels), and the smallest uniform relative
//   bias of the whole image detected with the given power.
#pragma once

#include <verity/stats/holm.h>
#include <verity/stats/kolmogorov_smirnov.h>
#include <verity/stats/pixel_statistics.h>
#include <verity/stats/tile_pooling.h>
#include <verity/stats/welch_t.h>

#include <array>
#include <vector>

namespace verity::validation {

struct TileTest {
  int tileX = 0, tileY = 0;  // tile indices
  TileRect rect;
  int channel = 0;
  PooledTile pooled;  // the two estimates; filled by the caller
  WelchResult welch;
  // (M_B − M_A) / ((|M_A| + |M_B|) / 2); 0 when both means are 0.
  double relativeDifference = 0;
  // The standard normal deviate with the same two-sided p-value, signed like M_B − M_A, so
  // that tests with different degrees of freedom compare; ±infinity for p = 0.
  double z = 0;
  // The smallest relative bias r (B's expectation × (1 + r)) of this tile that its test
  // rejects with probability `power` at level α/m; 0 for a deterministic test (any
  // difference is found), infinity when none up to 100 is.
  double detectableBias = 0;
  double adjustedP = 1;  // Holm
  bool rejected = false;
};

struct TileDecision {
  HolmResult holm;
  int deterministicTests = 0;
  std::array<KsResult, kChannels> uniformity;  // per channel
  double uniformityP = 1;  // Bonferroni-combined over the channels with ≥ 1 value
  double smallestP = 1;
  // The smallest uniform relative bias of B detected with probability `power` (power.h);
  // infinity when none is.
  double detectableBias = 0;
  bool differ = false;
};

// Fills each test's Welch result, z, relative difference, detectable bias, adjusted p and
// rejection from its `pooled` estimates, and decides the family at level `alpha` (in (0, 1));
// `power` in (0, 1). Requires at least one test (std::invalid_argument otherwise).
// Without `detectableBias` the power figures (bisections, most of the cost of a small family)
// are left NaN: for a sequential test's intermediate looks.
TileDecision decideTiles(std::vector<TileTest>& tests, double alpha, double power,
                         bool detectableBias = true);

}  // namespace verity::validation
