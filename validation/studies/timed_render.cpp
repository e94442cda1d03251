#include "validation/studies/timed_render.h"

#include <fmt/format.h>
#include <mpi.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <ctime>
#include <mutex>
#include <thread>

#include "core/error.h"
#include "distributed/distributed_render.h"
#include "validation/studies/seeds.h"
#include "validation/studies/study_scene.h"

namespace verity::studies {

namespace {

double cpuNow() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace

TimedRender timedRender(const SceneFile& file, const Sampler& prototype,
                        const Integrator& integrator, Film& film, int spp, int threads,
                        uint64_t seed, double timeLimit, ComponentImages* components,
                        const ProcessGroup& group) {
  if (group.distributed() && timeLimit > 0)
    throw VerityError("", "--time", "a time-limited render cannot be split over MPI ranks");
  RenderOptions options;
  options.components = components;
  options.threads = threads;
  options.samplesPerPixel = timeLimit > 0 ? (1 << 24) : spp;
  std::atomic<bool> cancel{false};
  options.cancel = &cancel;
  std::unique_ptr<Sampler> sampler = prototype.clone();
  sampler->setSeed(seed);

  // With a time limit, a watchdog raises the cancel flag, which render() checks between
  // passes (so every pixel keeps the same sample count).
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  std::thread watchdog;
  TimedRender out;
  const double cpu0 = cpuNow();
  const auto wall0 = std::chrono::steady_clock::now();
  if (timeLimit > 0)
    watchdog = std::thread([&] {
      std::unique_lock lock(m);
      if (!cv.wait_for(lock, std::chrono::duration<double>(timeLimit), [&] { return done; }))
        cancel = true;
    });
  out.stats = renderDistributed(group, *file.scene, integrator, *sampler, film, options);
  out.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  out.cpuSeconds = cpuNow() - cpu0;
  if (group.distributed()) {
    const double own = out.cpuSeconds;
    MPI_Reduce(&own, &out.cpuSeconds, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
  }
  if (watchdog.joinable()) {
    {
      std::lock_guard lock(m);
      done = true;
    }
    cv.notify_all();
    watchdog.join();
  }
  return out;
}

uint64_t renderBatches(const SceneFile& file, const std::string& integrator, int maxBounces,
                       int batches, int spp, const std::string& key,
                       const std::function<void(const Film&)>& onBatch) {
  const auto render = makeIntegrator(studyIntegrator(file, integrator, maxBounces));
  uint64_t invalid = 0;
  for (int batch = 0; batch < batches; ++batch) {
    Film film(file.scene->camera().resolution());
    RenderOptions options;
    options.samplesPerPixel = spp;
    const std::unique_ptr<Sampler> sampler = file.sampler->clone();
    sampler->setSeed(hashString(fmt::format("{} batch {}", key, batch)));
    invalid += verity::render(*file.scene, *render, *sampler, film, options).invalidSamples;
    onBatch(film);
  }
  return invalid;
}

}  // namespace verity::studies
