#include "validation/tile_pooling.h"

#include <stdexcept>

namespace verity::validation {

namespace {

// Accumulates Σ m_i, Σ s_i²/n_i and Σ (s_i²/n_i)²/(n_i − 1); the 1/P and 1/P² factors are
// applied once P is known.
struct Sums {
  double mean = 0, variance = 0, dfDenominator = 0;

  void add(double m, double s2, double n) {
    const double v = s2 / n;
    mean += m;
    variance += v;
    dfDenominator += v * v / (n - 1);
  }
  MeanEstimate estimate(int pixels) const {
    const double p = pixels, p2 = p * p;
    return {mean / p, variance / p2, dfDenominator / (p2 * p2)};
  }
};

}  // namespace

PooledTile poolTile(const PixelStatistics& a, const PixelStatistics& b, const TileRect& tile,
                    int channel, int minSamples) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("poolTile: the images differ in resolution");
  if (minSamples < 2) throw std::invalid_argument("poolTile: minSamples must be at least 2");
  if (tile.x0 < 0 || tile.y0 < 0 || tile.x1 > a.width || tile.y1 > a.height || tile.x0 >= tile.x1 ||
      tile.y0 >= tile.y1)
    throw std::invalid_argument("poolTile: the tile is not inside the image");
  Sums sa, sb;
  PooledTile out;
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      const size_t i = a.index(x, y);
      if (a.samples[i] < minSamples || b.samples[i] < minSamples) {
        ++out.excluded;
        continue;
      }
      sa.add(a.mean[channel][i], a.variance[channel][i], a.samples[i]);
      sb.add(b.mean[channel][i], b.variance[channel][i], b.samples[i]);
      ++out.pixels;
    }
  if (out.pixels > 0) {
    out.a = sa.estimate(out.pixels);
    out.b = sb.estimate(out.pixels);
  }
  return out;
}

}  // namespace verity::validation
