// The relative variance of one component image (a BDPT strategy's weighted or unweighted
// image, or a path-length image) of one render, against the length-k image r_k it is part of
// or estimates: the strategies study's measure of which strategy carries which light, and at
// what noise (Veach 1997, "Robust Monte Carlo Methods for Light Transport Simulation",
// ch. 10).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "film/film.h"

namespace verity::studies {

// The pixels whose mean is non-zero in some channel (of a length-k image: the pixels its
// strategies are averaged over).
std::vector<uint8_t> nonZeroPixels(const Film& film);

struct ComponentVariance {
  size_t pixels = 0;         // pixels averaged over
  double mean = 0;           // mean over those pixels and channels of the pixel means
  double standardError = 0;  // of `mean`: an upper bound (channels of a pixel correlate)
  // Mean over those pixels and channels of (variance of the pixel mean) / (r_k² + ε), with ε
  // = kRelEpsilon (relative_error.h) and r_k the pixel's mean in `lengthImage`.
  double relVariance = 0;
};
// Over the pixels where `pixels` is non-zero; all zero when there are none.
ComponentVariance componentVariance(const Film& film, const Film& lengthImage,
                                    const std::vector<uint8_t>& pixels);

}  // namespace verity::studies
