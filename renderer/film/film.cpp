#include "film/film.h"

#include <algorithm>
#include <cstring>
#include <numeric>

#include "core/hash.h"

namespace verity {

Film::Film(const Vector2i& resolution)
    : resolution_(resolution),
      sum_(size_t(resolution.x()) * resolution.y(), Eigen::Array3d::Zero()),
      sumSquares_(sum_.size(), Eigen::Array3d::Zero()),
      count_(sum_.size(), 0),
      invalid_(sum_.size(), 0) {}

bool Film::addSample(int x, int y, const Color3& value) {
  const size_t i = index(x, y);
  if (!value.allFinite()) {
    ++invalid_[i];
    return false;
  }
  const Eigen::Array3d v = value.cast<double>();
  sum_[i] += v;
  sumSquares_[i] += v * v;
  ++count_[i];
  if (!max_.empty()) max_[i] = max_[i].max(v);
  return true;
}

void Film::trackMaxima() {
  if (max_.empty()) max_.assign(sum_.size(), Eigen::Array3d::Zero());
}

void Film::addZeroSamples(uint32_t n) {
  for (auto& c : count_) c += n;
}

void Film::add(const Film& other) {
  for (size_t i = 0; i < sum_.size(); ++i) {
    sum_[i] += other.sum_[i];
    sumSquares_[i] += other.sumSquares_[i];
    count_[i] += other.count_[i];
    invalid_[i] += other.invalid_[i];
    if (!max_.empty() && !other.max_.empty()) max_[i] = max_[i].max(other.max_[i]);
  }
}

void Film::clear() {
  std::fill(sum_.begin(), sum_.end(), Eigen::Array3d::Zero());
  std::fill(sumSquares_.begin(), sumSquares_.end(), Eigen::Array3d::Zero());
  std::fill(count_.begin(), count_.end(), 0u);
  std::fill(invalid_.begin(), invalid_.end(), 0u);
  std::fill(max_.begin(), max_.end(), Eigen::Array3d::Zero());
}

Color3 Film::mean(int x, int y) const {
  const size_t i = index(x, y);
  if (count_[i] == 0) return Color3::Zero();
  return (sum_[i] / count_[i]).cast<float>();
}

Color3 Film::sampleVariance(int x, int y) const {
  const size_t i = index(x, y);
  const double n = count_[i];
  if (n < 2) return Color3::Zero();
  const Eigen::Array3d m = sum_[i] / n;
  return ((sumSquares_[i] - n * m * m) / (n - 1)).max(0.0).cast<float>();
}

uint64_t Film::invalidSamples() const {
  return std::accumulate(invalid_.begin(), invalid_.end(), uint64_t(0));
}

uint64_t Film::digest() const {
  uint64_t h = hashValues(resolution_.x(), resolution_.y());
  for (size_t i = 0; i < sum_.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      uint64_t bits[2];
      std::memcpy(&bits[0], &sum_[i][c], sizeof(double));
      std::memcpy(&bits[1], &sumSquares_[i][c], sizeof(double));
      h = hashValues(h, bits[0], bits[1]);
    }
    h = hashValues(h, count_[i], invalid_[i]);
  }
  return h;
}

uint64_t Film::validSamples() const {
  return std::accumulate(count_.begin(), count_.end(), uint64_t(0));
}

}  // namespace verity
