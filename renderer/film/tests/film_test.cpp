#include "film/film.h"

#include <gtest/gtest.h>

#include "film/image_io.h"

namespace verity {
namespace {

TEST(Film, NonFiniteSamplesAreCountedAndExcluded) {
  Film film(Vector2i(2, 1));
  EXPECT_TRUE(film.addSample(0, 0, Color3(1, 2, 3)));
  EXPECT_TRUE(film.addSample(0, 0, Color3(3, 2, 1)));
  EXPECT_FALSE(film.addSample(0, 0, Color3(std::nanf(""), 0, 0)));
  EXPECT_FALSE(film.addSample(0, 0, Color3(kInfinity, 0, 0)));
  EXPECT_EQ(film.count(0, 0), 2u);
  EXPECT_EQ(film.invalidSamples(), 2u);
  EXPECT_TRUE(film.mean(0, 0).isApprox(Color3(2, 2, 2)));
  // Sample variance of {1, 3} is 2, of {2, 2} is 0.
  EXPECT_TRUE(film.sampleVariance(0, 0).isApprox(Color3(2, 0, 2)));
  EXPECT_EQ(film.count(1, 0), 0u);
  EXPECT_TRUE(film.mean(1, 0).isZero());
}

TEST(Film, MaximaArePerChannelSkipInvalidSamplesAndMerge) {
  Film film(Vector2i(2, 1));
  film.addSample(0, 0, Color3(9, 9, 9));  // before tracking: not seen
  film.trackMaxima();
  film.addSample(0, 0, Color3(1, 5, 2));
  film.addSample(0, 0, Color3(4, 3, 2));
  film.addSample(0, 0, Color3(kInfinity, 0, 0));
  EXPECT_TRUE((film.maxSample(0, 0) == Color3(4, 5, 2)).all());
  EXPECT_TRUE(film.maxSample(1, 0).isZero());
  Film other(Vector2i(2, 1));
  other.trackMaxima();
  other.addSample(0, 0, Color3(0, 7, 0));
  other.addSample(1, 0, Color3(3, 0, 1));
  film.add(other);
  EXPECT_TRUE((film.maxSample(0, 0) == Color3(4, 7, 2)).all());
  EXPECT_TRUE((film.maxSample(1, 0) == Color3(3, 0, 1)).all());
  film.clear();
  EXPECT_TRUE(film.maxSample(0, 0).isZero());
}

TEST(ImageIo, ExrRoundTripKeepsChannelsAndAttributes) {
  Film film(Vector2i(3, 2));
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) {
      film.addSample(x, y, Color3(x, y, 0.25f));
      film.addSample(x, y, Color3(x + 1, y, 0.75f));
    }
  ImageChannels image = filmChannels(film, true);
  image.attributes["verity:spp"] = "2";
  const auto file = std::filesystem::temp_directory_path() / "verity_roundtrip.exr";
  writeExr(file, image);
  const ImageChannels back = readExr(file);
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.height, 2);
  EXPECT_EQ(back.attributes.at("verity:spp"), "2");
  for (const auto& [name, plane] : image.planes) EXPECT_EQ(back.planes.at(name), plane) << name;
  EXPECT_FLOAT_EQ(back.planes.at("R")[2 + 3], 2.5f);       // pixel (2, 1)
  EXPECT_FLOAT_EQ(back.planes.at("variance.R")[0], 0.5f);  // {0, 1}
  EXPECT_FLOAT_EQ(back.planes.at("samples")[0], 2.0f);
}

}  // namespace
}  // namespace verity
