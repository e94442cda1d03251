#include "distributed/distributed_render.h"

#include <fmt/format.h>

#include <chrono>
#include <csignal>
#include <cstdlib>

#include "core/error.h"
#include "distributed/film_transfer.h"
#include "render/pass_chunks.h"
#include "render/progress.h"

namespace verity {

namespace {

int chunkPasses(int chunk, int samplesPerPixel) {
  return std::min(kPassesPerChunk, samplesPerPixel - chunk * kPassesPerChunk);
}

// A hidden hook for the fault tests: VERITY_TEST_KILL_RANK=r makes rank r kill itself with
// SIGKILL after its first chunk, as a crashed node would.
void maybeDieForTest(const ProcessGroup& group) {
  const char* victim = std::getenv("VERITY_TEST_KILL_RANK");
  if (victim && std::atoi(victim) == group.rank()) std::raise(SIGKILL);
}

// Ranks 1 … N−1: render their chunks and send each to rank 0, the next rendering while the
// last travels. A chunk cut short by a cancel is sent and ends the rank's part.
void renderAndSend(const ProcessGroup& group, PassRenderer& passes, int samplesPerPixel,
                   const RenderOptions& options, const Vector2i& resolution) {
  Film films[2] = {Film(resolution), Film(resolution)};
  FilmSender senders[2];
  int k = 0;
  for (int chunk = group.rank(); chunk < chunkCount(samplesPerPixel); chunk += group.size(), ++k) {
    senders[k % 2].wait();
    Film& film = films[k % 2];
    const int done = renderChunk(passes, chunk, samplesPerPixel, film, options.cancel);
    senders[k % 2].send(0, chunk, done, film);
    maybeDieForTest(group);
    if (done < chunkPasses(chunk, samplesPerPixel)) break;
  }
}

// Rank 0: adds the chunks in chunk order, rendering its own and receiving the others'. Once a
// chunk comes back short, later chunks are still received (so that no rank blocks) but not
// added.
int renderAndReduce(const ProcessGroup& group, PassRenderer& passes, int samplesPerPixel,
                    const RenderOptions& options, Film& film, Progress& progress) {
  Film chunkFilm(film.resolution());
  std::vector<bool> stopped(group.size(), false);
  bool complete = true;
  int passesAdded = 0;
  for (int chunk = 0; chunk < chunkCount(samplesPerPixel); ++chunk) {
    const int owner = chunk % group.size();
    if (stopped[owner]) continue;
    int done = 0;
    if (owner == 0) {
      if (!complete) continue;  // rank 0's own chunks past the image's end: not rendered
      done = renderChunk(passes, chunk, samplesPerPixel, chunkFilm, options.cancel);
    } else {
      const ReceivedChunk received = receiveFilm(owner, chunkFilm);
      if (received.chunk != chunk)
        throw VerityError(
            "", fmt::format("MPI rank {}", owner),
            fmt::format("sent chunk {} where chunk {} was due", received.chunk, chunk));
      done = received.passes;
    }
    const bool whole = done == chunkPasses(chunk, samplesPerPixel);
    if (!whole) stopped[owner] = true;
    if (complete) {
      film.add(chunkFilm);
      passesAdded += done;
      progress.advance(uint64_t(done) * passes.tiles());
      complete = whole;
    }
  }
  return passesAdded;
}

}  // namespace

RenderStats renderDistributed(const ProcessGroup& group, const Scene& scene,
                              const Integrator& integrator, const Sampler& sampler, Film& film,
                              const RenderOptions& options) {
  if (!group.distributed()) return render(scene, integrator, sampler, film, options);
  if (options.components)
    throw VerityError("", "--strategies/--path-lengths",
                      "component images are rendered by one process only");
  const auto start = std::chrono::steady_clock::now();
  const int spp = options.samplesPerPixel;
  if (integrator.needsEmitters() && !scene.summary().hasEmitters()) {
    // Nothing can carry light: rank 0 alone writes the black image.
    return group.isRoot() ? render(scene, integrator, sampler, film, options) : RenderStats{};
  }

  PassRenderer passes(scene, integrator, sampler, film.resolution(), spp, options.threads);
  RenderStats stats;
  if (group.isRoot()) {
    Progress progress(uint64_t(spp) * passes.tiles(), options.progress);
    stats.passes = renderAndReduce(group, passes, spp, options, film, progress);
    progress.finish();
  } else {
    renderAndSend(group, passes, spp, options, film.resolution());
  }
  stats.interrupted = stats.passes < spp;

  // The job's rays and invalid splats, summed on rank 0.
  uint64_t local[2] = {passes.rays(), passes.invalidSplats()}, total[2] = {0, 0};
  MPI_Reduce(local, total, 2, MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
  stats.rays = total[0];
  stats.invalidSamples = total[1] + film.invalidSamples();
  stats.samples = uint64_t(stats.passes) * film.width() * film.height();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace verity
