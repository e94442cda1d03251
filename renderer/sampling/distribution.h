// Piecewise-constant distributions for sampling discrete choices (lights, triangles) and
// 2D tables (environment maps), by inverting the cumulative distribution.
#pragma once

#include <vector>

#include "core/math.h"

namespace verity {

class Distribution1D {
 public:
  Distribution1D() = default;
  // Weights must be finite and non-negative; all-zero weights give a uniform choice.
  explicit Distribution1D(std::vector<double> weights);

  size_t size() const { return pmf_.size(); }
  bool empty() const { return pmf_.empty(); }
  double total() const { return total_; }
  float pmf(size_t i) const { return pmf_[i]; }
  // Chooses an index; `u` is rescaled to a fresh uniform value in [0, 1) (for reuse).
  size_t sampleDiscrete(float u, float* pmf = nullptr, float* uRemapped = nullptr) const;
  // Samples a continuous position in [0, 1) with density pdf (piecewise constant).
  float sampleContinuous(float u, float* pdf, size_t* index = nullptr) const;
  float pdfContinuous(float x) const;

 private:
  std::vector<float> pmf_;
  std::vector<double> cdf_;  // size n+1, cdf_[0] = 0, cdf_[n] = 1
  double total_ = 0;
};

// Density over [0,1)² proportional to a rows × cols table (row-major, row 0 at y = 0).
class Distribution2D {
 public:
  Distribution2D() = default;
  Distribution2D(const std::vector<double>& weights, int cols, int rows);
  Point2f sample(const Point2f& u, float* pdf) const;
  float pdf(const Point2f& p) const;

 private:
  std::vector<Distribution1D> conditional_;  // per row, over columns
  Distribution1D marginal_;                  // over rows
};

}  // namespace verity
