// The z-score picture on a synthetic pair with known tile differences: no noise in the
// means, so every unchanged tile has t = 0 and every changed tile is rejected whatever the
// level; nothing here is random.
#include "validation/compare/z_score_image.h"

#include <gtest/gtest.h>
#include <stb_image.h>
#include <unistd.h>

#include <filesystem>
#include <set>

#include "core/error.h"
#include "validation/compare/variance_image_side.h"

namespace verity::validation {
namespace {

constexpr int kWidth = 64, kHeight = 32, kTile = 16;  // 4 × 2 tiles
constexpr int kSamples = 16;

// Each tile's left half bright red, its right half dark blue.
bool brightAt(int x) {
  return x % kTile < kTile / 2;
}

PixelStatistics stripes(double gainInTile21, double gainInTile11) {
  PixelStatistics s;
  s.label = "stripes";
  s.width = kWidth;
  s.height = kHeight;
  const size_t n = size_t(kWidth) * kHeight;
  for (int c = 0; c < kChannels; ++c) s.mean[c].resize(n), s.variance[c].resize(n);
  s.samples.assign(n, kSamples);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const int tx = x / kTile, ty = y / kTile;
      const double gain = tx == 2 && ty == 1 ? gainInTile21 : tx == 1 && ty == 1 ? gainInTile11 : 1;
      const double bright[3] = {2.0, 0.2, 0.1}, dark[3] = {0.01, 0.01, 0.08};
      for (int c = 0; c < kChannels; ++c) {
        const double mean = gain * (brightAt(x) ? bright[c] : dark[c]);
        s.mean[c][s.index(x, y)] = mean;
        s.variance[c][s.index(x, y)] = 0.01 * mean * mean;
      }
    }
  return s;
}

// B is brighter than A in tile (2, 1) and darker in tile (1, 1); tile (0, 0) has no samples
// in A, so it is not tested.
struct Pair {
  PixelStatistics a = stripes(1, 1), b = stripes(1.5, 0.5);
  Pair() {
    for (int y = 0; y < kTile; ++y)
      for (int x = 0; x < kTile; ++x) a.samples[a.index(x, y)] = 0;
  }
};

class ZScoreImage : public ::testing::Test {
 protected:
  void SetUp() override {
    result_ = compareImages(pair_.a, pair_.b, {kTile});
    ASSERT_TRUE(result_.differ);
    ASSERT_EQ(result_.tilesUntested, 1);
    mean_ = VarianceImageSide(pair_.a).meanImage();
  }
  // The picture's pixel at image pixel (x, y) of `panel`, offset (dx, dy) picture pixels
  // inside it.
  Rgb8 at(const ZScorePicture& p, const PixelRect& panel, int x, int y, int dx = 0,
          int dy = 0) const {
    return p.canvas.at(panel.x0 + x * p.scale + dx, panel.y0 + y * p.scale + dy);
  }

  Pair pair_;
  ComparisonResult result_;
  ImageChannels mean_;
};

TEST_F(ZScoreImage, ColourBarRunsFromBlueThroughGreyToRedWithTicksAndLabels) {
  const ZScorePicture p = drawZScorePicture(result_, mean_, "A: mean image");
  const PixelRect& bar = p.colourBar;
  ASSERT_GT(bar.x1 - bar.x0, 200);
  ASSERT_GT(bar.y1 - bar.y0, 10);
  ASSERT_LE(bar.y1 + 40, p.canvas.height());  // room for the ticks and labels below
  ASSERT_GE(bar.y0, p.zPanel.y1);
  const int middle = (bar.y0 + bar.y1) / 2;
  const Rgb8 left = p.canvas.at(bar.x0, middle), right = p.canvas.at(bar.x1 - 1, middle),
             centre = p.canvas.at((bar.x0 + bar.x1) / 2, middle);
  EXPECT_GT(left[2], left[0] + 40) << "B below A is blue";
  EXPECT_GT(right[0], right[2] + 40) << "B above A is red";
  EXPECT_LT(std::abs(centre[0] - centre[2]), 10) << "z = 0 is grey";
  // The bar's colour at its ends is the saturated map's, laid over the grey ramp.
  const Rgb8 saturated = divergingColour(-1e9, 1);
  EXPECT_NEAR(p.canvas.at(bar.x0, bar.y0)[2], std::lround(kZOpacity * saturated[2]), 1);
  // Tick marks under both ends, and text (black pixels) in the label rows below.
  EXPECT_EQ(p.canvas.at(bar.x0, bar.y1 + 2), (Rgb8{0, 0, 0}));
  EXPECT_EQ(p.canvas.at(bar.x1 - 1, bar.y1 + 2), (Rgb8{0, 0, 0}));
  int ink = 0;
  for (int y = bar.y1 + 8; y < p.canvas.height(); ++y)
    for (int x = bar.x0 - 20; x < bar.x1 + 20; ++x) ink += p.canvas.at(x, y) == Rgb8{0, 0, 0};
  EXPECT_GT(ink, 500) << "tick labels, sign convention and legend";
}

TEST_F(ZScoreImage, ImageIsVisibleUnderTheZScores) {
  const ZScorePicture p = drawZScorePicture(result_, mean_, "A: mean image");
  // Tile (3, 0) is tested and unchanged (z = 0): its stripes show through, bright red on
  // the left of the tile and dark blue on the right, in colour in the left panel and as
  // grey under the z colour in the right one.
  const int bright = 3 * kTile + 4, dark = 3 * kTile + 12, y = 8;
  const Rgb8 zBright = at(p, p.zPanel, bright, y), zDark = at(p, p.zPanel, dark, y);
  EXPECT_GT(zBright[1], zDark[1] + 60);
  const Rgb8 imageBright = at(p, p.imagePanel, bright, y), imageDark = at(p, p.imagePanel, dark, y);
  EXPECT_GT(imageBright[0], imageBright[2] + 100);
  EXPECT_GT(imageDark[2], imageDark[0] + 20);
  // The same inside the rejected tile (2, 1): the z colour does not hide the image.
  const Rgb8 rejectedBright = at(p, p.zPanel, 2 * kTile + 4, 24),
             rejectedDark = at(p, p.zPanel, 2 * kTile + 12, 24);
  EXPECT_GT(rejectedBright[1], rejectedDark[1] + 40);
}

TEST_F(ZScoreImage, RejectedTilesAreOutlinedWhereTheDifferenceIs) {
  const ZScorePicture p = drawZScorePicture(result_, mean_, "A: mean image");
  const std::set<std::pair<int, int>> changed = {{2, 1}, {1, 1}};
  for (const PixelRect* panel : {&p.imagePanel, &p.zPanel})
    for (int ty = 0; ty < 2; ++ty)
      for (int tx = 0; tx < 4; ++tx) {
        const bool outlined = changed.count({tx, ty}) > 0;
        // The tile's top-left corner, and the pixel inside it, in picture pixels.
        const Rgb8 corner = at(p, *panel, tx * kTile, ty * kTile),
                   inside = at(p, *panel, tx * kTile, ty * kTile, 1, 1),
                   farCorner = at(p, *panel, (tx + 1) * kTile, (ty + 1) * kTile, -1, -1);
        EXPECT_EQ(outlined, corner == (Rgb8{0, 0, 0}) && farCorner == (Rgb8{0, 0, 0}) &&
                                inside == (Rgb8{255, 255, 255}))
            << "tile " << tx << ", " << ty;
      }
  // Inside the outlines, the z colour says which way B differs, over a dark stripe.
  const Rgb8 above = at(p, p.zPanel, 2 * kTile + 12, 24), below = at(p, p.zPanel, kTile + 12, 24);
  EXPECT_GT(above[0], above[2] + 20) << "B above A: red";
  EXPECT_GT(below[2], below[0] + 20) << "B below A: blue";
}

TEST_F(ZScoreImage, UntestedTilesAreHatched) {
  const ZScorePicture p = drawZScorePicture(result_, mean_, "A: mean image");
  const auto stripes = [&](int tx, int ty) {
    int black = 0, white = 0;
    for (int dy = 0; dy < kTile * p.scale; ++dy)
      for (int dx = 0; dx < kTile * p.scale; ++dx) {
        const Rgb8 c = at(p, p.zPanel, tx * kTile, ty * kTile, dx, dy);
        black += c == Rgb8{0, 0, 0};
        white += c == Rgb8{255, 255, 255};
      }
    return std::min(black, white);
  };
  const int tilePixels = kTile * p.scale * kTile * p.scale;
  EXPECT_GT(stripes(0, 0), tilePixels / 8) << "the untested tile (0, 0)";
  EXPECT_EQ(stripes(3, 0), 0) << "the tested tile (3, 0)";
}

TEST_F(ZScoreImage, PngHoldsThePictureAndAnUnwritablePathIsNamed) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("verity-z-image-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "z.png";
  writeZScoreImage(file, result_, mean_, "A: mean image");
  const ZScorePicture p = drawZScorePicture(result_, mean_, "A: mean image");
  int width = 0, height = 0, channels = 0;
  unsigned char* read = stbi_load(file.string().c_str(), &width, &height, &channels, 3);
  ASSERT_NE(read, nullptr);
  EXPECT_EQ(width, p.canvas.width());
  EXPECT_EQ(height, p.canvas.height());
  EXPECT_TRUE(std::equal(p.canvas.pixels().begin(), p.canvas.pixels().end(), read));
  stbi_image_free(read);
  std::filesystem::remove_all(dir);
  try {
    writeZScoreImage(dir / "missing" / "z.png", result_, mean_, "A");
    FAIL() << "wrote into a missing folder";
  } catch (const VerityError& e) {
    EXPECT_NE(std::string(e.what()).find("missing/z.png"), std::string::npos) << e.what();
  }
}

TEST_F(ZScoreImage, ImageOfAnotherSizeIsRefused) {
  ImageChannels small = mean_;
  small.width /= 2;
  EXPECT_THROW(drawZScorePicture(result_, small, "A"), std::invalid_argument);
  ImageChannels noBlue = mean_;
  noBlue.planes.erase("B");
  EXPECT_THROW(drawZScorePicture(result_, noBlue, "A"), std::invalid_argument);
}

}  // namespace
}  // namespace verity::validation
