#include "validation/studies/strategy_variance.h"

#include <cmath>

#include "validation/studies/relative_error.h"

namespace verity::studies {

std::vector<uint8_t> nonZeroPixels(const Film& film) {
  std::vector<uint8_t> pixels(size_t(film.width()) * film.height(), 0);
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      pixels[size_t(y) * film.width() + x] = (film.mean(x, y) != 0).any();
  return pixels;
}

ComponentVariance componentVariance(const Film& film, const Film& lengthImage,
                                    const std::vector<uint8_t>& pixels) {
  ComponentVariance v;
  double sum = 0, errorSquares = 0, rel = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      if (!pixels[size_t(y) * film.width() + x]) continue;
      const uint32_t n = film.count(x, y);
      const Color3 variance =
          n > 0 ? Color3(film.sampleVariance(x, y) / float(n)) : Color3(Color3::Zero());
      const Color3 r = lengthImage.mean(x, y);
      ++v.pixels;
      sum += double(film.mean(x, y).sum()) / 3;
      // The channel average's standard deviation is at most the average of the channels'
      // (Minkowski), whatever their correlation; pixels are independent.
      const double sd = variance.cast<double>().sqrt().sum() / 3;
      errorSquares += sd * sd;
      for (int c = 0; c < 3; ++c) rel += variance[c] / (double(r[c]) * r[c] + kRelEpsilon);
    }
  if (v.pixels == 0) return v;
  v.mean = sum / double(v.pixels);
  v.standardError = std::sqrt(errorSquares) / double(v.pixels);
  v.relVariance = rel / (3.0 * double(v.pixels));
  return v;
}

}  // namespace verity::studies
