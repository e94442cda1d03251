// What each side shows under the z-scores (ComparisonSide::meanImage) and how it is made
// viewable (display_image.h).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "validation/compare/display_image.h"
#include "validation/compare/render_set_side.h"
#include "validation/compare/variance_image_side.h"

namespace verity::validation {
namespace {

// A 2 × 1 image whose pixels are (r, g, b) = value · (1, 2, 3), pixel 1 twice pixel 0.
ImageChannels rgb(float value) {
  ImageChannels image;
  image.width = 2;
  image.height = 1;
  for (int c = 0; c < kChannels; ++c)
    image.planes[kChannelNames[c]] = {value * (c + 1), 2 * value * (c + 1)};
  return image;
}

TEST(MeanImage, ASetShowsTheMeanOfItsRendersAndAVarianceImageItsMeans) {
  const RenderSetSide set({"one.exr", "two.exr", "three.exr"}, {rgb(1), rgb(2), rgb(6)}, "");
  const ImageChannels mean = set.meanImage();
  ASSERT_EQ(mean.width, 2);
  ASSERT_EQ(mean.height, 1);
  for (int c = 0; c < kChannels; ++c) {
    EXPECT_FLOAT_EQ(mean.planes.at(kChannelNames[c])[0], 3.0f * (c + 1));
    EXPECT_FLOAT_EQ(mean.planes.at(kChannelNames[c])[1], 6.0f * (c + 1));
  }
  PixelStatistics stats;
  stats.width = 2;
  stats.height = 1;
  for (int c = 0; c < kChannels; ++c) stats.mean[c] = {0.5 * c, 7.0};
  const ImageChannels means = VarianceImageSide(stats).meanImage();
  for (int c = 0; c < kChannels; ++c)
    EXPECT_EQ(means.planes.at(kChannelNames[c]), (std::vector<float>{0.5f * c, 7.0f}));
}

TEST(MeanImage, DisplayDoesNotDependOnExposureAndKeepsOrderAndHue) {
  // Reinhard's operator scales the log-average to middle grey: an image 1000 times brighter
  // looks the same (to rounding), the brighter pixel stays brighter, blue stays bluest.
  const DisplayImage dim = toneMapForDisplay(rgb(0.001f)), bright = toneMapForDisplay(rgb(1));
  for (int i = 0; i < 2; ++i)
    for (int c = 0; c < kChannels; ++c) {
      EXPECT_NEAR(dim.colour[i][c], bright.colour[i][c], 1) << i << " " << c;
      EXPECT_NEAR(dim.grey[i][c], bright.grey[i][c], 1) << i << " " << c;
    }
  EXPECT_GT(bright.grey[1][0], bright.grey[0][0] + 20);
  EXPECT_GT(bright.colour[0][2], bright.colour[0][0]);
  // Neither black nor white: the log-average is mid-grey.
  EXPECT_GT(bright.grey[0][0], 40);
  EXPECT_LT(bright.grey[1][0], 230);
}

TEST(MeanImage, NonFinitePixelsAreBlackAndLeftOutOfTheExposure) {
  ImageChannels image = rgb(1);
  image.planes["G"][1] = std::numeric_limits<float>::quiet_NaN();
  const DisplayImage shown = toneMapForDisplay(image);
  EXPECT_EQ(shown.colour[1], (Rgb8{0, 0, 0}));
  EXPECT_EQ(shown.grey[1], (Rgb8{0, 0, 0}));
  // Pixel 0 alone sets the exposure: its luminance becomes the key 0.18, shown as
  // 0.18 / 1.18 through the sRGB curve.
  const double expected = 255 * (1.055 * std::pow(0.18 / 1.18, 1 / 2.4) - 0.055);
  EXPECT_NEAR(shown.grey[0][0], expected, 1);
}

}  // namespace
}  // namespace verity::validation
