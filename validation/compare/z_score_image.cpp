#include "validation/compare/z_score_image.h"

#include <stb_image_write.h>

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <vector>

#include "core/error.h"

namespace verity::validation {

namespace {

// Moreland's cool-warm map at t = 0, 1/8, ..., 1 (8-bit sRGB), interpolated linearly.
constexpr unsigned char kCoolWarm[9][3] = {{59, 76, 192},   {98, 130, 234},  {141, 176, 254},
                                           {184, 208, 249}, {221, 221, 221}, {245, 196, 173},
                                           {244, 154, 123}, {222, 96, 77},   {180, 4, 38}};
constexpr std::array<unsigned char, 3> kUntested = {64, 64, 64};
constexpr std::array<unsigned char, 3> kRejectedOutline = {0, 0, 0};
constexpr int kMinimumWidth = 256;

}  // namespace

std::array<unsigned char, 3> divergingColour(double z, double zMax) {
  const double t = 0.5 + 0.5 * std::clamp(z / zMax, -1.0, 1.0);  // NaN cannot reach here
  const double position = t * 8;
  const int i = std::min(7, static_cast<int>(position));
  const double f = position - i;
  std::array<unsigned char, 3> rgb;
  for (int c = 0; c < 3; ++c)
    rgb[c] = static_cast<unsigned char>(
        std::lround((1 - f) * kCoolWarm[i][c] + f * kCoolWarm[i + 1][c]));
  return rgb;
}

void writeZScoreImage(const std::filesystem::path& file, const ComparisonResult& r) {
  const boost::math::normal normal;
  const double zMax = boost::math::quantile(
      boost::math::complement(normal, r.options.alpha / (2.0 * r.tests.size())));
  const TileGrid grid{r.width, r.height, r.options.tileSize};
  struct Mark {
    std::array<unsigned char, 3> colour = kUntested;
    bool rejected = false;
  };
  std::vector<Mark> marks(grid.count());
  // Tests are tile-major: a tile's channels are consecutive; the largest |z| colours it.
  double largest = -1;
  for (size_t i = 0; i < r.tests.size(); ++i) {
    const TileTest& t = r.tests[i];
    const bool first = i == 0 || r.tests[i - 1].tileX != t.tileX || r.tests[i - 1].tileY != t.tileY;
    Mark& mark = marks[t.tileY * grid.tilesX() + t.tileX];
    if (first) largest = -1;
    if (std::abs(t.z) > largest) {
      largest = std::abs(t.z);
      mark.colour = divergingColour(t.z, zMax);
    }
    mark.rejected |= t.rejected;
  }
  // Small images (this project's references are 32 to 64 pixels wide) are enlarged by a
  // whole factor k to at least kMinimumWidth, so that the tiles can be seen; outlines are
  // one pixel of the enlarged image.
  const int k = std::max(1, (kMinimumWidth + r.width - 1) / r.width);
  const int width = r.width * k, height = r.height * k;
  std::vector<unsigned char> pixels(size_t(width) * height * 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int tx = x / k / grid.tileSize, ty = y / k / grid.tileSize;
      const TileRect rect = grid.rect(tx, ty);
      const Mark& mark = marks[ty * grid.tilesX() + tx];
      const bool edge =
          x == rect.x0 * k || y == rect.y0 * k || x == rect.x1 * k - 1 || y == rect.y1 * k - 1;
      const auto& colour = mark.rejected && edge ? kRejectedOutline : mark.colour;
      std::copy(colour.begin(), colour.end(), pixels.begin() + 3 * (size_t(y) * width + x));
    }
  if (!stbi_write_png(file.string().c_str(), width, height, 3, pixels.data(), width * 3))
    throw VerityError(file.string(), "", "cannot write the z-score PNG");
}

}  // namespace verity::validation
