#include <verity/stats/tile_pooling.h>

#include <stdexcept>

namespace verity::validation {

std::vector<char> pixelsWithSamples(const PixelStatistics& s, int minSamples) {
  if (minSamples < 2) throw std::invalid_argument("pixelsWithSamples: minSamples must be >= 2");
  std::vector<char> usable(s.samples.size());
  for (size_t i = 0; i < usable.size(); ++i) usable[i] = s.samples[i] >= minSamples;
  return usable;
}

MeanEstimate poolPixels(const PixelStatistics& s, const TileRect& tile, int channel,
                        const std::vector<char>& usable, int* pixels) {
  if (usable.size() != size_t(s.width) * s.height)
    throw std::invalid_argument("poolPixels: the mask's size differs from the image's");
  if (tile.x0 < 0 || tile.y0 < 0 || tile.x1 > s.width || tile.y1 > s.height || tile.x0 >= tile.x1 ||
      tile.y0 >= tile.y1)
    throw std::invalid_argument("poolPixels: the tile is not inside the image");
  // Σ m_i, Σ s_i²/n_i and Σ (s_i²/n_i)²/(n_i − 1); the 1/P and 1/P² factors once P is known.
  double mean = 0, variance = 0, dfDenominator = 0;
  int count = 0;
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      const size_t i = s.index(x, y);
      if (!usable[i]) continue;
      const double n = s.samples[i];
      if (!(n >= 2)) throw std::invalid_argument("poolPixels: a marked pixel has < 2 samples");
      const double v = s.variance[channel][i] / n;
      mean += s.mean[channel][i];
      variance += v;
      dfDenominator += v * v / (n - 1);
      ++count;
    }
  *pixels = count;
  if (count == 0) return {};
  const double p = count, p2 = p * p;
  return {mean / p, variance / p2, dfDenominator / (p2 * p2)};
}

}  // namespace verity::validation
