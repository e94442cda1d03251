// render() (render/renderer.h) over every rank of a job: the chunks of passes
// (render/pass_chunks.h) are dealt round-robin, rank r rendering chunks r, r + N, …, and rank 0
// adds the chunk films in chunk order as they arrive, holding one at a time. The sums are
// the ones a single process makes, so the image is bit-identical for any number of ranks and
// threads.
#pragma once

#include "distributed/process_group.h"
#include "render/renderer.h"

namespace verity {

// Like render(); with several ranks only rank 0's `film` holds the image and its stats the
// whole job's. When `options.cancel` is raised (each rank's own signal), the image is the
// longest run of chunks, in chunk order, that were rendered whole, and the chunk after them
// as far as it got: every pixel has the same count, the one a render of stats.passes samples
// per pixel has. Component images are refused with several ranks.
RenderStats renderDistributed(const ProcessGroup& group, const Scene& scene,
                              const Integrator& integrator, const Sampler& sampler, Film& film,
                              const RenderOptions& options);

}  // namespace verity
