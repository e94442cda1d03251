// Renders timed by the wall clock and the process's CPU clock.
#pragma once

#include <cstdint>

#include "distributed/process_group.h"
#include "film/film.h"
#include "loader/scene_loader.h"
#include "render/renderer.h"

namespace verity::studies {

struct TimedRender {
  RenderStats stats;
  double wallSeconds = 0;  // around render() only: scene loading is not counted
  double cpuSeconds = 0;   // CPU time of the whole process (all threads) over the same span
};
// Renders `sampler`'s clones (seeded with `seed`) spp samples per pixel, or, with timeLimit > 0,
// passes until timeLimit seconds have passed (at least one pass; the last pass may overrun the
// limit). `components`, if given, records the per-strategy or per-path-length images as well. Over
// a distributed `group` (spp budgets only: a time limit would make the image depend on the ranks'
// speed) every rank renders its share, rank 0's film holds the image and cpuSeconds is the job's.
TimedRender timedRender(const SceneFile& file, const Sampler& sampler, const Integrator& integrator,
                        Film& film, int spp, int threads, uint64_t seed, double timeLimit = 0,
                        ComponentImages* components = nullptr,
                        const ProcessGroup& group = ProcessGroup::solo());

}  // namespace verity::studies
