#include "validation/studies/timed_render.h"

#include <mpi.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <ctime>
#include <mutex>
#include <thread>

#include "core/error.h"
#include "distributed/distributed_render.h"

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

}  // namespace verity::studies
