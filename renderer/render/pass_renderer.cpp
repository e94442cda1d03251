#include "render/pass_renderer.h"

#include <tbb/parallel_for.h>

namespace verity {

PassRenderer::PassRenderer(const Scene& scene, const Integrator& integrator,
                           const Sampler& prototype, const Vector2i& resolution,
                           int samplesPerPixel, int threads)
    : scene_(scene),
      integrator_(integrator),
      prototype_(prototype),
      resolution_(resolution),
      samplesPerPixel_(samplesPerPixel),
      passValues_(size_t(resolution.x()) * resolution.y()),
      passValid_(passValues_.size()),
      arena_(threads) {
  for (int y = 0; y < resolution.y(); y += kTileSize)
    for (int x = 0; x < resolution.x(); x += kTileSize)
      tiles_.push_back(
          {x, y, std::min(x + kTileSize, resolution.x()), std::min(y + kTileSize, resolution.y())});
  contexts_.resize(tiles_.size());
}

void PassRenderer::render(int pass, Film& film, ComponentImages* components) {
  const Camera& camera = scene_.camera();
  const int width = resolution_.x();
  if (components) components->startPass(tiles_.size());
  arena_.execute([&] {
    tbb::parallel_for(size_t(0), tiles_.size(), [&](size_t t) {
      const Tile& tile = tiles_[t];
      SampleContext& context = contexts_[t];
      context.splats.clear();
      if (components) context.components = &components->recorder(t);
      auto sampler = prototype_.clone();
      sampler->setSamplesPerPixel(samplesPerPixel_);
      for (int y = tile.y0; y < tile.y1; ++y) {
        for (int x = tile.x0; x < tile.x1; ++x) {
          sampler->startPixelSample(Point2i(x, y), pass);
          if (context.components) context.components->startPixel(Point2i(x, y));
          const Point2f filmPosition = Point2f(x, y) + sampler->next2D();
          const Ray ray = camera.generateRay(filmPosition, sampler->next2D());
          const Color3 L = integrator_.Li(scene_, *sampler, ray, context);
          // Tiles own disjoint pixels, so concurrent tiles never touch the same entry.
          const size_t i = size_t(y) * width + x;
          passValid_[i] = L.allFinite();
          passValues_[i] = passValid_[i] ? L : Color3::Zero();
        }
      }
      if (progress_) progress_->advance(1);
    });
  });
  for (const SampleContext& context : contexts_)
    for (const Splat& s : context.splats)
      passValues_[size_t(s.pixel.y()) * width + s.pixel.x()] += s.value;
  for (int y = 0; y < resolution_.y(); ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * width + x;
      if (passValid_[i])
        film.addSample(x, y, passValues_[i]);
      else
        film.addInvalidSample(x, y);
    }
  if (components) components->finishPass(passValid_);
}

uint64_t PassRenderer::rays() const {
  uint64_t n = 0;
  for (const SampleContext& context : contexts_) n += context.stats.rays;
  return n;
}

uint64_t PassRenderer::invalidSplats() const {
  uint64_t n = 0;
  for (const SampleContext& context : contexts_) n += context.invalidSplats;
  return n;
}

}  // namespace verity
