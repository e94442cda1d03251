#include "validation/compare/rgb_canvas.h"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>

namespace verity::validation {

namespace {

// stb_easy_font takes a mutable string; a vertex is x, y, z (floats) and 4 colour bytes.
constexpr int kVertexBytes = 16;
constexpr int kBytesPerCharacter = 270 * 2;  // its documented average is about 270

}  // namespace

RgbCanvas::RgbCanvas(int width, int height, Rgb8 background)
    : width_(width), height_(height), pixels_(size_t(width) * height * 3) {
  fill({0, 0, width, height}, background);
}

Rgb8 RgbCanvas::at(int x, int y) const {
  const unsigned char* p = &pixels_[3 * (size_t(y) * width_ + x)];
  return {p[0], p[1], p[2]};
}

void RgbCanvas::set(int x, int y, Rgb8 colour) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  std::copy(colour.begin(), colour.end(), pixels_.begin() + 3 * (size_t(y) * width_ + x));
}

void RgbCanvas::fill(const PixelRect& r, Rgb8 colour) {
  for (int y = std::max(0, r.y0); y < std::min(height_, r.y1); ++y)
    for (int x = std::max(0, r.x0); x < std::min(width_, r.x1); ++x) set(x, y, colour);
}

void RgbCanvas::text(int x, int y, const std::string& text, int scale, Rgb8 colour) {
  std::string mutableText = text;
  std::vector<char> vertices(kBytesPerCharacter * (text.size() + 1));
  const int quads = stb_easy_font_print(0, 0, mutableText.data(), nullptr, vertices.data(),
                                        static_cast<int>(vertices.size()));
  for (int q = 0; q < quads; ++q) {
    // The quads are axis-aligned with whole-pixel corners: fill their bounding box.
    float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
    for (int v = 0; v < 4; ++v) {
      const float* p = reinterpret_cast<const float*>(&vertices[kVertexBytes * (4 * q + v)]);
      x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
      y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
    }
    fill({x + int(std::lround(x0 * scale)), y + int(std::lround(y0 * scale)),
          x + int(std::lround(x1 * scale)), y + int(std::lround(y1 * scale))},
         colour);
  }
}

int RgbCanvas::textWidth(const std::string& text, int scale) {
  std::string mutableText = text;
  return stb_easy_font_width(mutableText.data()) * scale;
}

int RgbCanvas::lineHeight(int scale) {
  char line[] = "0";
  return stb_easy_font_height(line) * scale;
}

}  // namespace verity::validation
