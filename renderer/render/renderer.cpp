#include "render/renderer.h"

#include <chrono>

#include "render/pass_chunks.h"
#include "render/progress.h"

namespace verity {

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

  PassRenderer passes(scene, integrator, prototype, film.resolution(), spp, options.threads);
  Progress progress(uint64_t(spp) * passes.tiles(), options.progress);
  passes.reportTo(&progress);
  Film chunkFilm(film.resolution());
  if (film.tracksMaxima()) chunkFilm.trackMaxima();
  for (int chunk = 0; chunk < chunkCount(spp); ++chunk) {
    const int done = renderChunk(passes, chunk, spp, chunkFilm, options.cancel, options.components);
    film.add(chunkFilm);
    stats.passes += done;
    if (stats.passes < std::min(spp, (chunk + 1) * kPassesPerChunk)) {
      stats.interrupted = true;
      break;
    }
  }
  progress.finish();

  stats.rays = passes.rays();
  stats.invalidSamples = passes.invalidSplats() + film.invalidSamples();
  stats.samples = uint64_t(stats.passes) * film.width() * film.height();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace verity
