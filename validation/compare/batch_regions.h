// Region means of an image from independent batches, for integrators that splat.
//
// The tile pooling of image_comparison.h takes a tile's variance as Σ s_i²/n_i / P², which
// holds when pixels are independent. A light tracer or BDPT splats each light path onto
// several pixels of one pass, so pixels of a tile are positively correlated and that sum
// underestimates the tile's variance. Here the image is rendered as N independent batches
// (each its own seed); the mean over a region's pixels in one batch is one sample, so the
// region's variance is the sample variance of N i.i.d. batch values whatever the
// correlation between pixels (the method of batch means).
//
// `statistics()` returns the regions as a one-row PixelStatistics (region r at x = r) with
// N samples each, so compareImages with tileSize 1 runs one Welch test per region and
// channel, df from the N − 1 of each side.
#pragma once

#include <verity/stats/pixel_statistics.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "film/film.h"
#include "film/image_io.h"

namespace verity::validation {

class BatchRegions {
 public:
  // `regionOf` holds width·height region indices in [0, regions) or −1 (pixel left out),
  // row-major.
  BatchRegions(std::vector<int> regionOf, int regions, std::string label);

  // Adds one batch: a film of the image's resolution, rendered with its own seed. Throws
  // VerityError when the resolution differs.
  void addBatch(const Film& film);
  // The same for an image's R, G and B (another renderer's, read from an EXR).
  void addBatch(const ImageChannels& image);

  int batches() const { return batches_; }
  // Requires at least two batches. Regions with no pixel get 0 samples (compareImages leaves
  // them untested).
  PixelStatistics statistics() const;

 private:
  void addBatch(int width, int height, const std::function<Color3(int, int)>& mean);

  std::vector<int> regionOf_;
  std::vector<int> pixels_;  // per region
  std::string label_;
  int batches_ = 0;
  std::vector<std::array<double, kChannels>> sum_, sumSquares_;  // per region
};

// Square tiles of `tileSize` pixels over a width × height image (partial tiles at the right
// and bottom edges): the region index of each pixel, row-major, and the number of tiles.
std::vector<int> tileRegions(int width, int height, int tileSize, int* tiles);

}  // namespace verity::validation
