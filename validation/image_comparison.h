// Do two renders estimate the same image? Per-tile Welch t-tests (Jung, Hanika and
// Dachsbacher 2020, JCGT 9(2)) decided together by Holm's procedure, plus a check that the
// tiles' p-values are uniform.
//
// Choices:
// - Tiles of tileSize² pixels (16 by default), pooled by tile_pooling.h: the mean of the
//   pixel means, its variance Σ s_i²/n_i / P². Pooling makes each test's mean close to normal
//   (the t-test's assumption) and the family small; a bias confined to one pixel is diluted
//   by the tile's P pixels.
// - One test per colour channel, not one on luminance: the EXR stores each channel's
//   variance but not the covariances between channels that the variance of a luminance
//   would need, and a bias in one channel (a wrong blue albedo) would be weighted down by
//   luminance (0.07 for blue). The three tests of a tile are dependent; Holm's procedure
//   needs no independence.
// - The family: every test of every tile with at least one usable pixel, deterministic tests
//   (zero variance in both images: p = 1 for equal means, p = 0 otherwise) included, so that
//   an exact mismatch always fails. The images DIFFER when Holm rejects any test at the
//   family-wise level alpha (1% by default): a correct pair is reported as different with
//   probability at most alpha.
// - Uniformity (kolmogorov_smirnov.h): a KS test per channel over the non-deterministic tiles'
//   p-values (tiles are independent, channels are not), combined by Bonferroni over the
//   channels tested. It is a diagnostic and does NOT enter the decision: heavy-tailed
//   estimators violate its assumptions in correct renders.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "validation/pixel_statistics.h"
#include "validation/stats/holm.h"
#include "validation/stats/kolmogorov_smirnov.h"
#include "validation/stats/welch_t.h"
#include "validation/tile_pooling.h"

namespace verity::validation {

struct ComparisonOptions {
  int tileSize = 16;
  double alpha = 0.01;  // family-wise level of the Holm decision
  int minSamples = 2;   // per pixel, in both images
  double power = 0.9;   // for the detectable-bias figure
};

struct TileTest {
  int tileX = 0, tileY = 0;  // tile indices
  TileRect rect;
  int channel = 0;
  PooledTile pooled;
  WelchResult welch;
  // (M_B − M_A) / ((|M_A| + |M_B|) / 2); 0 when both means are 0.
  double relativeDifference = 0;
  double adjustedP = 1;  // Holm
  bool rejected = false;
};

struct ComparisonResult {
  ComparisonOptions options;
  std::string labelA, labelB;
  int width = 0, height = 0, tilesX = 0, tilesY = 0;
  int tilesTested = 0, tilesUntested = 0;  // untested: no pixel with enough samples
  int pixelsExcluded = 0;                  // pixels with too few samples in either image
  int deterministicTests = 0;
  std::vector<TileTest> tests;  // tile-major, then channel
  HolmResult holm;
  std::array<KsResult, kChannels> uniformity;  // per channel
  double uniformityP = 1;  // Bonferroni-combined over the channels with ≥ 1 value
  double smallestP = 1;
  // The smallest uniform relative bias of B detected with probability options.power
  // (power.h); infinity when none is.
  double detectableBias = 0;
  bool differ = false;
  std::vector<std::string> warnings;  // from the images' attributes

  // Indices into `tests`, smallest p first (ties: larger |relative difference| first).
  std::vector<size_t> worst(size_t count) const;
};

// Throws VerityError naming both images when their resolutions differ or no tile can be
// tested, and naming the option when an option is out of range.
ComparisonResult compareImages(const PixelStatistics& a, const PixelStatistics& b,
                               const ComparisonOptions& options = {});

}  // namespace verity::validation
