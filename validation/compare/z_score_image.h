// A picture of where two images differ, to place each tile in the scene. Two panels of the
// image's size (an image narrower than 256 pixels enlarged by a whole factor to at least
// 256), tile columns numbered above them and tile rows beside them as the report numbers
// tiles:
// - left, the mean image given (the compare command gives side A's), tone-mapped for display
//   (display_image.h);
// - right, the same image as grey luminance under each tested tile's z: the z of its most
//   significant channel (TileTest::z, the normal deviate of the Welch p-value, signed like
//   B − A) on Moreland's cool-warm diverging map (K. Moreland 2009, "Diverging Color Maps
//   for Scientific Visualization", ISVC): blue where B is below A, red where above, fully
//   saturated from the Bonferroni threshold z_c = Φ⁻¹(1 − α/(2m)) (Holm's first step) on.
//   The colour's opacity grows with |z| up to kZOpacity at z_c, so the image stays visible
//   everywhere and unveiled where z = 0; a grey underlay keeps the hues readable.
// Tiles Holm rejects are outlined (black outside, white inside, visible on any image) in
// both panels; untested tiles are hatched in the right one. Below: the colour bar from −z_c
// to z_c with ticks and labels, laid over a grey ramp from black to white as the overlay is
// over dark and bright parts of the image, the sign convention and a legend.
#pragma once

#include <array>
#include <filesystem>
#include <string>

#include "film/image_io.h"
#include "validation/compare/image_comparison.h"
#include "validation/compare/rgb_canvas.h"

namespace verity::validation {

inline constexpr double kZOpacity = 0.6;

// The colour of z on the map saturating at ±zMax (8-bit sRGB).
Rgb8 divergingColour(double z, double zMax);

// Where the z colours saturate: the Bonferroni threshold z_c over the result's tests.
double zScoreSaturation(const ComparisonResult& result);

struct ZScorePicture {
  RgbCanvas canvas;
  int scale = 1;         // picture pixels per image pixel, in each direction
  PixelRect imagePanel;  // the image in colour
  PixelRect zPanel;      // z over the image's grey
  PixelRect colourBar;   // z = −z_c at its left edge, z_c at its right
};

// `image`: planes R, G, B (linear) at the result's resolution, e.g. a side's meanImage();
// `imageCaption` says whose it is ("A: mean of 8 renders"). Throws std::invalid_argument
// when the image has another resolution or lacks a plane.
ZScorePicture drawZScorePicture(const ComparisonResult& result, const ImageChannels& image,
                                const std::string& imageCaption);

// Draws the picture and writes it as PNG; throws VerityError naming the file when it cannot.
void writeZScoreImage(const std::filesystem::path& file, const ComparisonResult& result,
                      const ImageChannels& image, const std::string& imageCaption);

}  // namespace verity::validation
