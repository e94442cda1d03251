// Renders an image in passes of one sample per pixel over 16×16 tiles on a TBB task arena.
// Every sample's random numbers depend only on (the sampler's seed, pixel, sample index), each
// tile is written by one task, and passes are summed in fixed chunks (render/pass_chunks.h), so
// the image is bit-identical for any thread count or schedule, and for any number of processes
// (distributed/). Stopping between passes leaves every pixel with the same number of samples.
#pragma once

#include <atomic>

#include "film/film.h"
#include "integrators/integrator.h"
#include "render/component_images.h"

namespace verity {

struct RenderOptions {
  int samplesPerPixel = 1;
  int threads = 0;  // 0: all cores
  bool progress = false;
  const std::atomic<bool>* cancel = nullptr;  // checked between passes
  // Per-strategy or per-path-length images to fill besides the film; null: none.
  ComponentImages* components = nullptr;
};

struct RenderStats {
  int passes = 0;  // samples per pixel completed
  bool interrupted = false;
  bool tracedNoRays = false;  // the scene could not carry light, so nothing was traced
  double seconds = 0;
  uint64_t rays = 0;
  uint64_t samples = 0;
  uint64_t invalidSamples = 0;
};

// `sampler` is the prototype every tile clones: its seed (Sampler::setSeed) is the render's one
// seed.
RenderStats render(const Scene& scene, const Integrator& integrator, const Sampler& sampler,
                   Film& film, const RenderOptions& options);

}  // namespace verity
