// Do two renders estimate the same image? Per-tile Welch t-tests (Jung, Hanika and
// Dachsbacher 2020, JCGT 9(2)) decided together by Holm's procedure, plus a check that the
// tiles' p-values are uniform.
//
// Choices:
// - Each side is one image with per-pixel variances (variance_image_side.h) or a set of
//   independent renders (render_set_side.h); both are pooled over the same pixels: those
//   usable on both sides.
// - Tiles of tileSize² pixels (16 by default), pooled by tile_pooling.h: the mean of the
//   pixel means, its variance Σ s_i²/n_i / P² (or, for a set, from the renders' spread).
//   Pooling makes each test's mean close to normal (the t-test's assumption) and the family
//   small; a bias confined to one pixel is diluted by the tile's P pixels.
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

#include <verity/stats/pixel_statistics.h>
#include <verity/stats/tile_decision.h>

#include <string>
#include <vector>

#include "validation/compare/comparison_side.h"

namespace verity::validation {

struct ComparisonOptions {
  int tileSize = 16;
  double alpha = 0.01;  // family-wise level of the Holm decision
  int minSamples = 2;   // per pixel, in an image with variances
  double power = 0.9;   // for the detectable-bias figures
  // The detectable-bias figures (NaN without): off for a sequential test's intermediate looks,
  // whose cost they dominate.
  bool detectableBias = true;
};

struct ComparisonResult : TileDecision {
  ComparisonOptions options;
  std::string labelA, labelB;
  SideSummary sideA, sideB;
  int width = 0, height = 0, tilesX = 0, tilesY = 0;
  int tilesTested = 0, tilesUntested = 0;  // untested: no pixel usable on both sides
  int pixelsExcluded = 0;                  // pixels not usable on both sides
  std::vector<TileTest> tests;             // tile-major, then channel
  std::vector<std::string> warnings;       // from the images' attributes

  // Indices into `tests`, smallest p first (ties: larger |relative difference| first).
  std::vector<size_t> worst(size_t count) const;
};

// Throws VerityError naming the option that is out of range.
void checkComparisonOptions(const ComparisonOptions& options);

// Throws VerityError naming both sides when their resolutions differ or no tile can be
// tested, and naming the option when an option is out of range.
ComparisonResult compareSides(const ComparisonSide& a, const ComparisonSide& b,
                              const ComparisonOptions& options = {});
// Two images with per-pixel variances.
ComparisonResult compareImages(const PixelStatistics& a, const PixelStatistics& b,
                               const ComparisonOptions& options = {});

}  // namespace verity::validation
