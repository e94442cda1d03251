#include "render/renderer.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <optional>

#include "render/progress.h"

namespace verity {

namespace {
struct Tile {
  int x0, y0, x1, y1;
};

std::vector<Tile> makeTiles(const Vector2i& res) {
  std::vector<Tile> tiles;
  for (int y = 0; y < res.y(); y += kTileSize)
    for (int x = 0; x < res.x(); x += kTileSize)
      tiles.push_back({x, y, std::min(x + kTileSize, res.x()), std::min(y + kTileSize, res.y())});
  return tiles;
}
}  // namespace

RenderStats render(const Scene& scene, const Integrator& integrator, const Sampler& prototype,
                   Film& film, const RenderOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  RenderStats stats;
  const int spp = options.samplesPerPixel;
  if (integrator.needsEmitters() && !scene.summary().hasEmitters()) {
    // Nothing can carry light: the image is exactly black.
    film.addZeroSamples(static_cast<uint32_t>(spp));
    if (options.components) options.components->addZeroSamples(static_cast<uint32_t>(spp));
    stats.passes = spp;
    stats.samples = uint64_t(spp) * film.width() * film.height();
    stats.tracedNoRays = true;
    return stats;
  }

  const std::vector<Tile> tiles = makeTiles(film.resolution());
  std::vector<SampleContext> contexts(tiles.size());
  const Camera& camera = scene.camera();
  const int width = film.width();
  // This pass's value of every pixel: its own camera sample plus the splats that land on it.
  // Together they are one independent sample of the pixel, so per-pixel sums of squares give
  // a valid variance for splatting integrators too.
  std::vector<Color3> passValues(size_t(width) * film.height());
  std::vector<uint8_t> passValid(passValues.size());
  Progress progress(uint64_t(spp) * tiles.size(), options.progress);
  // TBB caps its workers at the core count unless told otherwise; an explicit thread count
  // beyond it (oversubscription, tests of 3 threads on 2 cores) must still get its threads.
  std::optional<tbb::global_control> allowThreads;
  if (options.threads > 0)
    allowThreads.emplace(
        tbb::global_control::max_allowed_parallelism,
        std::max<size_t>(options.threads, tbb::global_control::active_value(
                                              tbb::global_control::max_allowed_parallelism)));
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);

  for (int pass = 0; pass < spp; ++pass) {
    if (options.cancel && options.cancel->load()) {
      stats.interrupted = true;
      break;
    }
    if (options.components) options.components->startPass(tiles.size());
    arena.execute([&] {
      tbb::parallel_for(size_t(0), tiles.size(), [&](size_t t) {
        const Tile& tile = tiles[t];
        SampleContext& context = contexts[t];
        context.splats.clear();
        if (options.components) context.components = &options.components->recorder(t);
        auto sampler = prototype.clone();
        sampler->setSamplesPerPixel(spp);
        for (int y = tile.y0; y < tile.y1; ++y) {
          for (int x = tile.x0; x < tile.x1; ++x) {
            sampler->startPixelSample(Point2i(x, y), pass);
            if (context.components) context.components->startPixel(Point2i(x, y));
            const Point2f filmPosition = Point2f(x, y) + sampler->next2D();
            const Ray ray = camera.generateRay(filmPosition, sampler->next2D());
            const Color3 L = integrator.Li(scene, *sampler, ray, context);
            // Tiles own disjoint pixels, so concurrent tiles never touch the same entry.
            const size_t i = size_t(y) * width + x;
            passValid[i] = L.allFinite();
            passValues[i] = passValid[i] ? L : Color3::Zero();
          }
        }
        progress.advance(1);
      });
    });
    for (const SampleContext& context : contexts)
      for (const Splat& s : context.splats)
        passValues[size_t(s.pixel.y()) * width + s.pixel.x()] += s.value;
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < width; ++x) {
        const size_t i = size_t(y) * width + x;
        if (passValid[i])
          film.addSample(x, y, passValues[i]);
        else
          film.addInvalidSample(x, y);
      }
    if (options.components) options.components->finishPass(passValid);
    stats.passes = pass + 1;
  }
  progress.finish();

  for (const SampleContext& context : contexts) {
    stats.rays += context.stats.rays;
    stats.invalidSamples += context.invalidSplats;
  }
  stats.invalidSamples += film.invalidSamples();
  stats.samples = uint64_t(stats.passes) * film.width() * film.height();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace verity
