// A film that tracks its largest sample per pixel (Film::trackMaxima, which `verity bench`
// reads to count fireflies) keeps it through render(), which accumulates passes in a film of
// its own before adding them to the caller's.
#include <gtest/gtest.h>

#include <filesystem>

#include "loader/scene_loader.h"
#include "render/renderer.h"

namespace verity {
namespace {

TEST(SampleMaxima, RenderKeepsEachPixelsLargestSample) {
  SceneFile file =
      loadScene(std::filesystem::path(VERITY_SOURCE_DIR) / "scenes" / "cornell-box.json",
                SceneOverrides::atWidth(16));
  const auto integrator = makeIntegrator(file.integrator);
  Film film(file.scene->camera().resolution());
  film.trackMaxima();
  RenderOptions options;
  options.samplesPerPixel = 4;
  file.sampler->setSeed(5);
  render(*file.scene, *integrator, *file.sampler, film, options);
  int lit = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const Color3 mean = film.mean(x, y), largest = film.maxSample(x, y);
      // The largest of a pixel's samples is at least their mean, channel by channel.
      EXPECT_TRUE((largest >= mean * (1 - 1e-5f)).all())
          << "pixel (" << x << ", " << y << "): largest " << largest.transpose() << ", mean "
          << mean.transpose();
      if ((mean > 0).any()) ++lit;
    }
  EXPECT_GT(lit, film.width() * film.height() / 2);
}

}  // namespace
}  // namespace verity
