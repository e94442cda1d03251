// Per-pixel accumulation of samples in double precision: sum, sum of squares and count, so
// that the mean and its variance can be written. Non-finite samples are counted and left
// out, never averaged in. On request it also keeps each pixel's largest sample per channel,
// which shows fireflies: a single sample far above the pixel's value.
#pragma once

#include <span>
#include <vector>

#include "core/math.h"

namespace verity {

class Film {
 public:
  explicit Film(const Vector2i& resolution);

  // Adds one sample of pixel (x, y); returns false (and counts it) if it is NaN or Inf.
  bool addSample(int x, int y, const Color3& value);
  // Counts a sample that was NaN or Inf (and so left out).
  void addInvalidSample(int x, int y) { ++invalid_[index(x, y)]; }
  // Counts `n` zero-valued samples in every pixel (renders that need no ray).
  void addZeroSamples(uint32_t n);
  // Adds another film's sums, sums of squares and counts pixel by pixel (same resolution).
  void add(const Film& other);
  // Back to no samples at all.
  void clear();
  // From now on keep each pixel's largest valid sample per channel (off by default: it costs
  // a comparison per sample and a fourth accumulator). Films moved between processes do not
  // carry it.
  void trackMaxima();
  bool tracksMaxima() const { return !max_.empty(); }
  // The largest valid sample per channel since tracking began (zero where there is none).
  Color3 maxSample(int x, int y) const { return max_[index(x, y)].cast<float>(); }

  const Vector2i& resolution() const { return resolution_; }
  int width() const { return resolution_.x(); }
  int height() const { return resolution_.y(); }
  uint32_t count(int x, int y) const { return count_[index(x, y)]; }
  // Mean of the valid samples (zero where there are none).
  Color3 mean(int x, int y) const;
  // Unbiased sample variance of one sample, per channel (zero below two samples).
  Color3 sampleVariance(int x, int y) const;
  uint64_t invalidSamples() const;
  uint64_t validSamples() const;
  // A hash of every accumulator's bits: two films with the same digest summed the same numbers
  // in the same order, which images rounded to float cannot show.
  uint64_t digest() const;

  // The accumulators themselves, pixel-major, for moving a film between processes
  // (distributed/film_transfer.h).
  std::span<Eigen::Array3d> sums() { return sum_; }
  std::span<Eigen::Array3d> sumSquares() { return sumSquares_; }
  std::span<uint32_t> counts() { return count_; }
  std::span<uint32_t> invalidCounts() { return invalid_; }

 private:
  size_t index(int x, int y) const { return size_t(y) * resolution_.x() + x; }

  Vector2i resolution_;
  std::vector<Eigen::Array3d> sum_, sumSquares_;
  std::vector<Eigen::Array3d> max_;  // empty unless trackMaxima() was called
  std::vector<uint32_t> count_, invalid_;
};

}  // namespace verity
