// The fake renderer's images (test support): a small image whose pixels are independent draws
// around known tile means, so that the referee's error rates can be measured against the truth.
// The program fake_renderer.cpp writes them as EXRs; FakeRenderSource makes the same images in
// the process, for the calibrations' hundreds of decisions.
#pragma once

#include <cstdint>
#include <string>

#include "film/image_io.h"
#include "validation/referee/render_source.h"

namespace verity::validation::testing {

struct FakeScene {
  int width = 8, height = 8, tileSize = 4;
  // Pixel value = μ_t,c (1 + bias on the biased tiles) X, E[X] = 1, sd(X) = noise:
  // X normal, or log-normal (heavy-tailed, skewed like Monte Carlo pixel estimates).
  double noise = 0.25;
  bool heavyTails = false;
  double bias = 0;
  int biasedTiles = -1;    // the first this many tiles (row-major) are biased; −1: all
  int biasedChannels = 3;  // in R, G and B, or in the first this many
};

// The expectation of tile `tile`'s channel c, before the bias: 0.5 + 0.25 (tile mod 4), times
// 1 + 0.2 c.
double fakeTileMean(int tile, int channel);

// One render with its own seed: R, G and B planes.
ImageChannels fakeRender(const FakeScene& scene, uint64_t seed);

// Side A renders scene `a`, side B scene `b`, in the process.
class FakeRenderSource : public RenderSource {
 public:
  FakeRenderSource(FakeScene a, FakeScene b) : a_(a), b_(b) {}
  // In the process at once: no deadline can pass.
  std::vector<Rendered> render(const std::vector<RenderRequest>& requests,
                               RenderDeadline deadline) override;

 private:
  FakeScene a_, b_;
};

}  // namespace verity::validation::testing
