#include "validation/compare/z_score_image.h"

#include <fmt/format.h>
#include <stb_image_write.h>

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/error.h"
#include "validation/compare/display_image.h"

namespace verity::validation {

namespace {

// Moreland's cool-warm map at t = 0, 1/8, ..., 1 (8-bit sRGB), interpolated linearly.
constexpr unsigned char kCoolWarm[9][3] = {{59, 76, 192},   {98, 130, 234},  {141, 176, 254},
                                           {184, 208, 249}, {221, 221, 221}, {245, 196, 173},
                                           {244, 154, 123}, {222, 96, 77},   {180, 4, 38}};
constexpr Rgb8 kBlack = {0, 0, 0}, kWhite = {255, 255, 255};
constexpr int kMinimumPanelWidth = 256;
constexpr int kMargin = 8, kPanelGap = 16, kBarHeight = 24, kTickLength = 6;
constexpr int kHatchPeriod = 8;  // diagonal stripes, one black and one white per period
constexpr int kLargeText = 2;    // font scale of the colour bar's labels

// The z colour's opacity over the image: none at z = 0, kZOpacity from z_c on, so that
// tiles without a difference show the image unveiled.
double zOpacity(double z, double zMax) {
  return kZOpacity * std::min(1.0, std::abs(z) / zMax);
}

Rgb8 blend(Rgb8 under, Rgb8 over, double opacity) {
  Rgb8 out;
  for (int c = 0; c < 3; ++c)
    out[c] = static_cast<unsigned char>(std::lround((1 - opacity) * under[c] + opacity * over[c]));
  return out;
}

// The larger font scale at which `text` fits `width` pixels.
int fittingScale(const std::string& text, int width) {
  return RgbCanvas::textWidth(text, kLargeText) <= width ? kLargeText : 1;
}

// The smallest of 1, 2, 5, 10, 20, 50, ... that is at least `minimum`.
int niceStep(double minimum) {
  for (int decade = 1;; decade *= 10)
    for (int m : {1, 2, 5})
      if (m * decade >= minimum) return m * decade;
}

struct TileMark {
  Rgb8 colour = kBlack;
  double opacity = 0;
  bool tested = false, rejected = false;
};

// Tests are tile-major: a tile's channels are consecutive; the largest |z| colours it.
std::vector<TileMark> tileMarks(const ComparisonResult& r, const TileGrid& grid, double zMax) {
  std::vector<TileMark> marks(grid.count());
  double largest = -1;
  for (size_t i = 0; i < r.tests.size(); ++i) {
    const TileTest& t = r.tests[i];
    const bool first = i == 0 || r.tests[i - 1].tileX != t.tileX || r.tests[i - 1].tileY != t.tileY;
    TileMark& mark = marks[t.tileY * grid.tilesX() + t.tileX];
    if (first) largest = -1;
    if (std::abs(t.z) > largest) {
      largest = std::abs(t.z);
      mark.colour = divergingColour(t.z, zMax);
      mark.opacity = zOpacity(t.z, zMax);
    }
    mark.tested = true;
    mark.rejected |= t.rejected;
  }
  return marks;
}

// The outline of a rejected tile at distance `inset` from its edge: black, then white.
const Rgb8* outline(int inset) {
  return inset == 0 ? &kBlack : inset == 1 ? &kWhite : nullptr;
}

const Rgb8* hatch(int x, int y) {
  const int phase = (x + y) % kHatchPeriod;
  return phase < 2                                                   ? &kBlack
         : phase >= kHatchPeriod / 2 && phase < kHatchPeriod / 2 + 2 ? &kWhite
                                                                     : nullptr;
}

// Tile columns numbered above `panel`, rows beside it (left or right), every `step` tiles.
void numberTiles(RgbCanvas& canvas, const PixelRect& panel, const TileGrid& grid, int k,
                 bool rowsOnLeft) {
  const int tilePixels = grid.tileSize * k;
  const int columnStep =
      niceStep(double(RgbCanvas::textWidth(std::to_string(grid.tilesX() - 1), 1) + 6) / tilePixels);
  const int rowStep = niceStep(double(RgbCanvas::kCapHeight + 4) / tilePixels);
  for (int tx = 0; tx < grid.tilesX(); tx += columnStep) {
    const std::string label = std::to_string(tx);
    const TileRect rect = grid.rect(tx, 0);
    const int centre = panel.x0 + (rect.x0 + rect.x1) * k / 2;
    canvas.text(centre - RgbCanvas::textWidth(label, 1) / 2, panel.y0 - RgbCanvas::kCapHeight - 3,
                label, 1, kBlack);
  }
  for (int ty = 0; ty < grid.tilesY(); ty += rowStep) {
    const std::string label = std::to_string(ty);
    const TileRect rect = grid.rect(0, ty);
    const int y = panel.y0 + (rect.y0 + rect.y1) * k / 2 - RgbCanvas::kCapHeight / 2;
    canvas.text(rowsOnLeft ? panel.x0 - 3 - RgbCanvas::textWidth(label, 1) : panel.x1 + 4, y, label,
                1, kBlack);
  }
}

// Labels of the colour bar's ticks: ±z_c at its ends, and whole z values between where
// they leave room.
void drawColourBarTicks(RgbCanvas& canvas, const PixelRect& bar, double zMax) {
  const double pixelsPerZ = (bar.x1 - bar.x0) / (2 * zMax);
  const auto xOf = [&](double z) {
    return std::min(bar.x1 - 1, bar.x0 + int(std::lround((z + zMax) * pixelsPerZ)));
  };
  const int labelY = bar.y1 + kTickLength + 3;
  const auto tick = [&](double z, const std::string& label) {
    const int x = xOf(z);
    canvas.fill({x, bar.y1, x + 1, bar.y1 + kTickLength}, kBlack);
    canvas.text(x - RgbCanvas::textWidth(label, kLargeText) / 2, labelY, label, kLargeText, kBlack);
  };
  const std::string end = fmt::format("{:.2f}", zMax);
  tick(-zMax, "-" + end);
  tick(zMax, end);
  const int gap = RgbCanvas::textWidth("0", kLargeText);
  const int step = niceStep((RgbCanvas::textWidth("-00", kLargeText) + gap) / pixelsPerZ);
  for (int z = -step * int(zMax / step); z <= zMax; z += step) {
    const std::string label = std::to_string(z);
    const double clearance = (RgbCanvas::textWidth("-" + end, kLargeText) / 2.0 +
                              RgbCanvas::textWidth(label, kLargeText) / 2.0 + gap) /
                             pixelsPerZ;
    if (std::abs(z) <= zMax - clearance) tick(z, label);
  }
}

}  // namespace

Rgb8 divergingColour(double z, double zMax) {
  const double t = 0.5 + 0.5 * std::clamp(z / zMax, -1.0, 1.0);  // NaN cannot reach here
  const double position = t * 8;
  const int i = std::min(7, static_cast<int>(position));
  const double f = position - i;
  Rgb8 rgb;
  for (int c = 0; c < 3; ++c)
    rgb[c] = static_cast<unsigned char>(
        std::lround((1 - f) * kCoolWarm[i][c] + f * kCoolWarm[i + 1][c]));
  return rgb;
}

double zScoreSaturation(const ComparisonResult& r) {
  const boost::math::normal normal;
  return boost::math::quantile(
      boost::math::complement(normal, r.options.alpha / (2.0 * r.tests.size())));
}

ZScorePicture drawZScorePicture(const ComparisonResult& r, const ImageChannels& image,
                                const std::string& imageCaption) {
  if (image.width != r.width || image.height != r.height)
    throw std::invalid_argument(
        fmt::format("drawZScorePicture: the image has {}x{} pixels, the comparison {}x{}",
                    image.width, image.height, r.width, r.height));
  const DisplayImage display = toneMapForDisplay(image);
  const double zMax = zScoreSaturation(r);
  const TileGrid grid{r.width, r.height, r.options.tileSize};
  const std::vector<TileMark> marks = tileMarks(r, grid, zMax);

  // Layout, top to bottom: captions, tile column numbers, the panels, the bar's title, the
  // bar, its tick labels, the sign convention, the legend.
  const int k = std::max(1, (kMinimumPanelWidth + r.width - 1) / r.width);
  const int panelWidth = r.width * k, panelHeight = r.height * k;
  const int side = kMargin + RgbCanvas::textWidth(std::to_string(grid.tilesY() - 1), 1) + 4;
  const int width = 2 * side + 2 * panelWidth + kPanelGap;
  const std::string zCaption = "z of B - A over the grey image";
  const int captionScale =
      std::min(fittingScale(imageCaption, panelWidth), fittingScale(zCaption, panelWidth));
  const int panelY = kMargin + RgbCanvas::kCapHeight * captionScale + 4 + RgbCanvas::kCapHeight + 4;
  const std::string title = fmt::format(
      "z per tile: full colour from |z| = z_c = {:.2f} (Bonferroni, alpha {:g}, {} tests)", zMax,
      r.options.alpha, r.tests.size());
  const int titleScale = fittingScale(title, width - 2 * kMargin);
  const int titleY = panelY + panelHeight + 14;
  const int endLabel = RgbCanvas::textWidth(fmt::format("-{:.2f}", zMax), kLargeText) / 2 + 2;
  const int barY = titleY + RgbCanvas::kCapHeight * titleScale + 6;
  const PixelRect bar{side + endLabel, barY, width - side - endLabel, barY + kBarHeight};
  const int signY = bar.y1 + kTickLength + 3 + RgbCanvas::kCapHeight * kLargeText + 8;
  const int legendY = signY + RgbCanvas::kCapHeight * kLargeText + 10;
  const int legendBox = RgbCanvas::kCapHeight * kLargeText;
  const int height = legendY + legendBox + kMargin;

  ZScorePicture picture{RgbCanvas(width, height, kWhite), k, {}, {}, bar};
  RgbCanvas& canvas = picture.canvas;
  picture.imagePanel = {side, panelY, side + panelWidth, panelY + panelHeight};
  picture.zPanel = {side + panelWidth + kPanelGap, panelY, width - side, panelY + panelHeight};
  canvas.text(picture.imagePanel.x0, kMargin, imageCaption, captionScale, kBlack);
  canvas.text(picture.zPanel.x0, kMargin, zCaption, captionScale, kBlack);
  numberTiles(canvas, picture.imagePanel, grid, k, true);
  numberTiles(canvas, picture.zPanel, grid, k, false);

  for (int py = 0; py < panelHeight; ++py)
    for (int px = 0; px < panelWidth; ++px) {
      const int x = px / k, y = py / k;
      const int tx = x / grid.tileSize, ty = y / grid.tileSize;
      const TileMark& mark = marks[ty * grid.tilesX() + tx];
      const TileRect rect = grid.rect(tx, ty);
      const int inset = std::min(
          {px - rect.x0 * k, py - rect.y0 * k, rect.x1 * k - 1 - px, rect.y1 * k - 1 - py});
      const size_t i = size_t(y) * r.width + x;
      const Rgb8* ring = mark.rejected ? outline(inset) : nullptr;
      const Rgb8* stripe = mark.tested ? nullptr : hatch(px, py);
      const Rgb8 z =
          mark.tested ? blend(display.grey[i], mark.colour, mark.opacity) : display.grey[i];
      canvas.set(picture.imagePanel.x0 + px, panelY + py, ring ? *ring : display.colour[i]);
      canvas.set(picture.zPanel.x0 + px, panelY + py, ring ? *ring : stripe ? *stripe : z);
    }

  canvas.text(kMargin, titleY, title, titleScale, kBlack);
  for (int x = bar.x0; x < bar.x1; ++x) {
    const double z = ((x - bar.x0 + 0.5) / (bar.x1 - bar.x0) * 2 - 1) * zMax;
    for (int y = bar.y0; y < bar.y1; ++y) {
      const auto grey =
          static_cast<unsigned char>(std::lround(255.0 * (y - bar.y0) / (kBarHeight - 1)));
      canvas.set(x, y, blend({grey, grey, grey}, divergingColour(z, zMax), zOpacity(z, zMax)));
    }
  }
  drawColourBarTicks(canvas, bar, zMax);
  const std::string below = "<- B below A", above = "B above A ->";
  canvas.text(bar.x0, signY, below, kLargeText, kBlack);
  canvas.text(bar.x1 - RgbCanvas::textWidth(above, kLargeText), signY, above, kLargeText, kBlack);

  // The legend: a sample of each marking, then what it means.
  int x = bar.x0;
  for (const bool rejected : {true, false}) {
    for (int py = 0; py < legendBox; ++py)
      for (int px = 0; px < legendBox; ++px) {
        const int inset = std::min({px, py, legendBox - 1 - px, legendBox - 1 - py});
        const Rgb8* mark = rejected ? outline(inset) : hatch(px, py);
        canvas.set(x + px, legendY + py, mark ? *mark : Rgb8{160, 160, 160});
      }
    const std::string text = rejected ? "rejected by Holm" : "untested";
    canvas.text(x + legendBox + 6, legendY, text, kLargeText, kBlack);
    x += legendBox + 6 + RgbCanvas::textWidth(text, kLargeText) + 24;
  }
  return picture;
}

void writeZScoreImage(const std::filesystem::path& file, const ComparisonResult& r,
                      const ImageChannels& image, const std::string& imageCaption) {
  const ZScorePicture picture = drawZScorePicture(r, image, imageCaption);
  const RgbCanvas& c = picture.canvas;
  if (!stbi_write_png(file.string().c_str(), c.width(), c.height(), 3, c.pixels().data(),
                      c.width() * 3))
    throw VerityError(file.string(), "", "cannot write the z-score PNG");
}

}  // namespace verity::validation
