// Errors of a render against a reference image: the relative MSE of the studies.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "film/film.h"
#include "film/image_io.h"

namespace verity::studies {

// The ε in the denominator of the relative squared error (x − r)² / (r² + ε), the relative
// MSE of the adaptive-sampling literature (Rousselle, Knaus and Zwicker 2011, "Adaptive
// Sampling and Reconstruction using Greedy Error Minimization"): it keeps black and
// near-black pixels from dominating the mean. Issue 6 fixes ε = 1e-2.
inline constexpr double kRelEpsilon = 1e-2;

// Errors of an image against a reference of the same size (means in planes R, G, B).
struct ErrorStats {
  double relMse = 0;        // mean over pixels and channels of (x − r)² / (r² + ε)
  double meanVariance = 0;  // mean over pixels and channels of the variance of the pixel mean
  double relVariance = 0;   // mean of that variance / (r² + ε): relMse's expectation if unbiased
  size_t pixelsUsed = 0;    // pixels with a finite reference and at least one sample
};
ErrorStats compareToReference(const Film& film, const ImageChannels& reference);
// Per pixel sqrt(mean over channels of (x − r)² / (r² + ε)), row 0 at the top.
std::vector<float> relativeErrorImage(const Film& film, const ImageChannels& reference);
// The reference's own estimated relative MSE: mean of (variance / samples) / (r² + ε).
double referenceRelMse(const ImageChannels& reference);

}  // namespace verity::studies
