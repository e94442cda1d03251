#include "sampling/distribution.h"

#include <numeric>

namespace verity {

Distribution1D::Distribution1D(std::vector<double> weights) {
  const size_t n = weights.size();
  if (n == 0) return;
  total_ = std::accumulate(weights.begin(), weights.end(), 0.0);
  if (!(total_ > 0)) std::fill(weights.begin(), weights.end(), 1.0);
  const double sum = total_ > 0 ? total_ : static_cast<double>(n);
  cdf_.resize(n + 1);
  pmf_.resize(n);
  cdf_[0] = 0;
  for (size_t i = 0; i < n; ++i) {
    pmf_[i] = static_cast<float>(weights[i] / sum);
    cdf_[i + 1] = cdf_[i] + weights[i] / sum;
  }
  cdf_[n] = 1.0;
}

size_t Distribution1D::sampleDiscrete(float u, float* pmf, float* uRemapped) const {
  // Last index whose cdf is <= u, skipping zero-probability entries.
  auto it = std::upper_bound(cdf_.begin(), cdf_.end(), static_cast<double>(u));
  size_t i = std::clamp<size_t>(static_cast<size_t>(it - cdf_.begin()), 1, pmf_.size()) - 1;
  while (pmf_[i] == 0 && i + 1 < pmf_.size()) ++i;
  if (pmf) *pmf = pmf_[i];
  if (uRemapped) {
    const double width = cdf_[i + 1] - cdf_[i];
    *uRemapped =
        width > 0 ? std::min(static_cast<float>((u - cdf_[i]) / width), kOneMinusEpsilon) : 0.0f;
  }
  return i;
}

float Distribution1D::sampleContinuous(float u, float* pdf, size_t* index) const {
  float remapped = 0;
  const size_t i = sampleDiscrete(u, nullptr, &remapped);
  if (index) *index = i;
  if (pdf) *pdf = pmf_[i] * static_cast<float>(pmf_.size());
  return std::min((static_cast<float>(i) + remapped) / static_cast<float>(pmf_.size()),
                  kOneMinusEpsilon);
}

float Distribution1D::pdfContinuous(float x) const {
  if (pmf_.empty() || x < 0 || x >= 1) return 0;
  const size_t i = std::min(static_cast<size_t>(x * pmf_.size()), pmf_.size() - 1);
  return pmf_[i] * static_cast<float>(pmf_.size());
}

Distribution2D::Distribution2D(const std::vector<double>& weights, int cols, int rows) {
  std::vector<double> rowSums(rows);
  for (int y = 0; y < rows; ++y) {
    std::vector<double> row(weights.begin() + size_t(y) * cols,
                            weights.begin() + size_t(y + 1) * cols);
    conditional_.emplace_back(row);
    rowSums[y] = conditional_.back().total();
  }
  marginal_ = Distribution1D(rowSums);
}

Point2f Distribution2D::sample(const Point2f& u, float* pdf) const {
  float pdfY = 0, pdfX = 0;
  size_t row = 0;
  const float y = marginal_.sampleContinuous(u.y(), &pdfY, &row);
  const float x = conditional_[row].sampleContinuous(u.x(), &pdfX);
  if (pdf) *pdf = pdfX * pdfY;
  return {x, y};
}

float Distribution2D::pdf(const Point2f& p) const {
  if (p.y() < 0 || p.y() >= 1) return 0;
  const size_t row =
      std::min(static_cast<size_t>(p.y() * conditional_.size()), conditional_.size() - 1);
  return marginal_.pdfContinuous(p.y()) * conditional_[row].pdfContinuous(p.x());
}

}  // namespace verity
