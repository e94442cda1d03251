// Errors of a render against a reference image: the relative MSE of the studies.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "film/film.h"
#include "film/image_io.h"

namespace verity::studies {

// The ε in the denominator of the relative squared error (x − r)² / (r² + ε), the relative
// MSE of the adaptive-sampling literature (Rousselle, Knaus and Zwicker 2011, "Adaptive
// Sampling and Reconstruction using Greedy Error Minimization"): it keeps black and
// near-black pixels from dominating the mean. Every study uses ε = 1e-2, so that their relative
// MSEs compare.
inline constexpr double kRelEpsilon = 1e-2;

// One channel's relative squared error (x − r)² / (r² + ε).
inline double relativeSquaredError(double x, double r) {
  return (x - r) * (x - r) / (r * r + kRelEpsilon);
}

// Errors of an image against a reference of the same size (means in planes R, G, B).
struct ErrorStats {
  double relMse = 0;        // mean over pixels and channels of (x − r)² / (r² + ε)
  double meanVariance = 0;  // mean over pixels and channels of the variance of the pixel mean
  double relVariance = 0;   // mean of that variance / (r² + ε): relMse's expectation if unbiased
  size_t pixelsUsed = 0;    // pixels with a finite reference and at least one sample
};
// Reads a reference image (an EXR with planes R, G and B), or throws VerityError naming `file`.
ImageChannels readReference(const std::filesystem::path& file);
// `reference` holds planes R, G and B (readReference) and is as large as `film`.
ErrorStats compareToReference(const Film& film, const ImageChannels& reference);
// The relative MSE of an image from any renderer, its planes `rgb` (R, G, B), against
// `reference`: pixels with a non-finite reference are left out, as compareToReference does.
// Throws VerityError naming `file` when the sizes differ or a used pixel is not finite.
double imageRelMse(const ImageChannels& image, const std::array<std::string, 3>& rgb,
                   const ImageChannels& reference, const std::string& file);
// Fireflies: pixels whose error comes from one sample far above the reference. A pixel of n
// samples holds a far sample when, in some channel, its largest sample m exceeds the reference
// r by so much that this sample alone moves the pixel mean by more than `k` units of the
// relative error: (m − r) / n > k·sqrt(r² + ε). With k = 1 that one sample alone gives the
// pixel a relative squared error of at least 1.
struct FireflyShare {
  size_t pixels = 0;        // pixels holding a far sample
  double relMseSum = 0;     // their (x − r)² / (r² + ε), summed over channels
  double allRelMseSum = 0;  // the same over every pixel compareToReference uses
  double share() const { return allRelMseSum > 0 ? relMseSum / allRelMseSum : 0; }
};
// `film` must keep its maxima (Film::trackMaxima before rendering).
FireflyShare fireflyShare(const Film& film, const ImageChannels& reference, double k = 1);
// Per pixel sqrt(mean over channels of (x − r)² / (r² + ε)), row 0 at the top.
std::vector<float> relativeErrorImage(const Film& film, const ImageChannels& reference);
// The reference's own estimated relative MSE: mean of (variance / samples) / (r² + ε).
double referenceRelMse(const ImageChannels& reference);

}  // namespace verity::studies
