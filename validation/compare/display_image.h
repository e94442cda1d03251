// A linear RGB image (a side's mean, comparison_side.h) made viewable in 8-bit sRGB, with
// Reinhard's global photographic operator (E. Reinhard, M. Stark, P. Shirley and J. Ferwerda
// 2002, "Photographic Tone Reproduction for Digital Images", SIGGRAPH, eqs. 1-3): the
// log-average luminance is scaled to middle grey (key 0.18) and L/(1 + L) compresses the
// highlights, so that renders of any exposure, light sources in view, show their scene.
// The colour is scaled with its luminance, then encoded with the exact sRGB curve.
#pragma once

#include <vector>

#include "film/image_io.h"
#include "validation/compare/rgb_canvas.h"

namespace verity::validation {

struct DisplayImage {
  int width = 0, height = 0;
  std::vector<Rgb8> colour;  // row-major
  std::vector<Rgb8> grey;    // the tone-mapped luminance only
};

// Throws std::invalid_argument when `image` lacks planes R, G or B. Non-finite pixels are
// left out of the log-average and shown black.
DisplayImage toneMapForDisplay(const ImageChannels& image);

}  // namespace verity::validation
