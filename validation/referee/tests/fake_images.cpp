#include "validation/referee/tests/fake_images.h"

#include <cmath>
#include <random>

namespace verity::validation::testing {

double fakeTileMean(int tile, int channel) {
  return (0.5 + 0.25 * (tile % 4)) * (1 + 0.2 * channel);
}

ImageChannels fakeRender(const FakeScene& scene, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal;
  // Log-normal with mean 1 and standard deviation `noise`: σ² = ln(1 + noise²).
  const double sigma = std::sqrt(std::log1p(scene.noise * scene.noise));
  ImageChannels image;
  image.width = scene.width;
  image.height = scene.height;
  const int tilesX = (scene.width + scene.tileSize - 1) / scene.tileSize;
  for (int c = 0; c < 3; ++c) {
    std::vector<float>& plane = image.planes[std::string(1, "RGB"[c])];
    plane.resize(size_t(scene.width) * scene.height);
    for (int y = 0; y < scene.height; ++y)
      for (int x = 0; x < scene.width; ++x) {
        const int tile = (y / scene.tileSize) * tilesX + x / scene.tileSize;
        const bool biased =
            (scene.biasedTiles < 0 || tile < scene.biasedTiles) && c < scene.biasedChannels;
        const double mean = fakeTileMean(tile, c) * (1 + (biased ? scene.bias : 0.0));
        const double z = normal(random);
        const double factor =
            scene.heavyTails ? std::exp(sigma * z - 0.5 * sigma * sigma) : 1 + scene.noise * z;
        plane[size_t(y) * scene.width + x] = float(mean * factor);
      }
  }
  return image;
}

std::vector<Rendered> FakeRenderSource::render(const std::vector<RenderRequest>& requests,
                                               RenderDeadline) {
  std::vector<Rendered> out;
  for (const RenderRequest& r : requests)
    out.push_back({fakeRender(r.side == Side::A ? a_ : b_, r.seed),
                   "fake-" + std::to_string(r.seed) + ".exr"});
  return out;
}

}  // namespace verity::validation::testing
