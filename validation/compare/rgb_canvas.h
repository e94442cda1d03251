// An 8-bit sRGB raster for drawing pictures of comparisons (z_score_image.h): rectangles,
// blending and text. Text comes from stb_easy_font (Debian's libstb-dev, which the project
// already uses for PNG): a public-domain ASCII font built of axis-aligned quads, so it is
// drawn here by filling rectangles, enlarged by a whole factor.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace verity::validation {

using Rgb8 = std::array<unsigned char, 3>;

// A rectangle of pixels [x0, x1) × [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

class RgbCanvas {
 public:
  RgbCanvas(int width, int height, Rgb8 background);

  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<unsigned char>& pixels() const { return pixels_; }  // row-major RGB
  Rgb8 at(int x, int y) const;

  void set(int x, int y, Rgb8 colour);  // ignores pixels outside the canvas
  void fill(const PixelRect& rect, Rgb8 colour);
  // The text's top-left corner at (x, y), each font pixel `scale` × `scale` pixels.
  void text(int x, int y, const std::string& text, int scale, Rgb8 colour);

  // Size of `text` at `scale`: the advance of its characters, and one line's height
  // (capitals and digits fill the top kCapHeight · scale of it).
  static int textWidth(const std::string& text, int scale);
  static int lineHeight(int scale);
  static constexpr int kCapHeight = 7;

 private:
  int width_, height_;
  std::vector<unsigned char> pixels_;
};

}  // namespace verity::validation
