// The exact sRGB transfer curve (IEC 61966-2-1): PNG output encodes with it, image textures
// decode with it.
#pragma once

namespace verity {

float srgbToLinear(float v);
float linearToSrgb(float v);

}  // namespace verity
