// A picture of where two images differ, at the images' resolution so that it overlays them
// (an image narrower than 256 pixels enlarged by a whole factor to at least 256):
// each tested tile is filled with the colour of its most significant channel's z-score
// (TileTest::z, the normal deviate of the Welch p-value, signed like B − A) on Moreland's
// cool-warm diverging map (K. Moreland 2009, "Diverging Color Maps for Scientific
// Visualization", ISVC): blue where B is below A, red where above, light grey at 0, fully
// saturated from the Bonferroni threshold z_c = Φ⁻¹(1 − α/(2m)) (Holm's first step) on.
// Tiles Holm rejects are outlined in black; untested tiles are dark grey.
#pragma once

#include <array>
#include <filesystem>

#include "validation/compare/image_comparison.h"

namespace verity::validation {

// The colour of z on the map saturating at ±zMax (8-bit sRGB).
std::array<unsigned char, 3> divergingColour(double z, double zMax);

// Writes the PNG; throws VerityError naming the file when it cannot.
void writeZScoreImage(const std::filesystem::path& file, const ComparisonResult& result);

}  // namespace verity::validation
