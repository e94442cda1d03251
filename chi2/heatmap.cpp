#include "chi2/heatmap.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/error.h"

// Static definitions: this file's private copy of the writer, which cannot clash with
// another translation unit that defines the implementation.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

namespace verity::chi2 {

namespace {

constexpr int kPixelsPerCell = 8;

// Cell values to an RGB image, rows from the top of the domain (cos θ = 1) down.
template <class ColorOf>
void writeImage(const Domain& d, const std::string& path, ColorOf colorOf) {
  const int w = d.nx * kPixelsPerCell, h = d.ny * kPixelsPerCell;
  std::vector<uint8_t> rgb(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int cell = (d.ny - 1 - y / kPixelsPerCell) * d.nx + x / kPixelsPerCell;
      const auto c = colorOf(cell);
      for (int k = 0; k < 3; ++k) rgb[(size_t(y) * w + x) * 3 + k] = c[k];
    }
  if (!stbi_write_png(path.c_str(), w, h, 3, rgb.data(), w * 3))
    throw VerityError("", "", "cannot write \"" + path + "\"");
}

std::array<uint8_t, 3> gray(double t) {
  const auto v = static_cast<uint8_t>(std::lround(255 * std::clamp(t, 0.0, 1.0)));
  return {v, v, v};
}

}  // namespace

std::vector<std::string> writeHeatmaps(const TestResult& r, const std::string& prefix) {
  double scale = 0;
  for (size_t i = 0; i < r.expected.size(); ++i)
    scale = std::max({scale, r.expected[i], double(r.observed[i])});
  if (scale <= 0) scale = 1;
  const std::vector<std::string> paths = {prefix + "_observed.png", prefix + "_expected.png",
                                          prefix + "_difference.png"};
  writeImage(r.domain, paths[0], [&](int c) { return gray(r.observed[c] / scale); });
  writeImage(r.domain, paths[1], [&](int c) { return gray(r.expected[c] / scale); });
  writeImage(r.domain, paths[2], [&](int c) {
    const double e = r.expected[c], o = double(r.observed[c]);
    double z = e > 0 ? (o - e) / std::sqrt(e) : (o > 0 ? 5.0 : 0.0);
    z = std::clamp(z / 5, -1.0, 1.0);
    const auto hi = static_cast<uint8_t>(255),
               lo = static_cast<uint8_t>(std::lround(255 * (1 - std::fabs(z))));
    return z >= 0 ? std::array<uint8_t, 3>{hi, lo, lo} : std::array<uint8_t, 3>{lo, lo, hi};
  });
  return paths;
}

}  // namespace verity::chi2
