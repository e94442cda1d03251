#include "validation/z_score_image.h"

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
  std::vector<unsigned char> pixels(size_t(r.width) * r.height * 3);
  const auto fill = [&](const TileRect& rect, const std::array<unsigned char, 3>& rgb,
                        bool outline) {
    for (int y = rect.y0; y < rect.y1; ++y)
      for (int x = rect.x0; x < rect.x1; ++x) {
        const bool edge = x == rect.x0 || y == rect.y0 || x == rect.x1 - 1 || y == rect.y1 - 1;
        const auto& colour = outline && edge ? kRejectedOutline : rgb;
        std::copy(colour.begin(), colour.end(), pixels.begin() + 3 * (size_t(y) * r.width + x));
      }
  };
  const TileGrid grid{r.width, r.height, r.options.tileSize};
  for (int ty = 0; ty < r.tilesY; ++ty)
    for (int tx = 0; tx < r.tilesX; ++tx) fill(grid.rect(tx, ty), kUntested, false);
  // Tests are tile-major: a tile's channels are consecutive.
  for (size_t i = 0; i < r.tests.size();) {
    size_t worst = i;
    bool rejected = false;
    size_t j = i;
    for (; j < r.tests.size() && r.tests[j].tileX == r.tests[i].tileX &&
           r.tests[j].tileY == r.tests[i].tileY;
         ++j) {
      if (std::abs(r.tests[j].z) > std::abs(r.tests[worst].z)) worst = j;
      rejected |= r.tests[j].rejected;
    }
    const TileRect& rect = r.tests[i].rect;
    fill(rect, divergingColour(r.tests[worst].z, zMax),
         rejected && rect.x1 - rect.x0 >= 3 && rect.y1 - rect.y0 >= 3);
    i = j;
  }
  if (!stbi_write_png(file.string().c_str(), r.width, r.height, 3, pixels.data(), r.width * 3))
    throw VerityError(file.string(), "", "cannot write the z-score PNG");
}

}  // namespace verity::validation
