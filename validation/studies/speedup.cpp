#include "validation/studies/speedup.h"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.h"
#include "validation/studies/run_distribution.h"
#include "validation/studies/seeds.h"
#include "validation/studies/study_scene.h"
#include "validation/studies/timed_render.h"

namespace verity::studies {

namespace {

// What tells one run of the study from another.
struct SpeedupRunKey {
  std::string scene;
  int width, height;
  std::string integrator;
  int maxBounces, threads, spp, repeat;
  auto operator<=>(const SpeedupRunKey&) const = default;
};

SpeedupRunKey speedupRunKey(const FieldReader& r) {
  return {r.text("scene"),          r.integer("width"),   r.integer("height"), r.text("integrator"),
          r.integer("max_bounces"), r.integer("threads"), r.integer("spp"),    r.integer("repeat")};
}

}  // namespace

StudyProgress runSpeedupStudy(const SpeedupConfig& config,
                              const std::function<void(const std::string&)>& log,
                              const ProcessGroup& group) {
  if (config.threads.empty()) throw VerityError("", "--threads", "no thread count given");
  const SceneFile file = loadScene(config.scene, SceneOverrides::atWidth(config.resolution));
  std::vector<PreparedIntegrator> integrators =
      prepareIntegrators(file, config.integrators, config.maxBounces);
  const Vector2i resolution = file.scene->camera().resolution();
  const MachineInfo machine = machineInfo();
  KeyedStudyOutput output(config.output, "speedup", speedupRunKey);

  std::vector<StudyRun> runs;
  for (int repeat = 0; repeat < config.repeats; ++repeat) {
    std::vector<int> order = config.threads;
    if (repeat % 2) std::reverse(order.begin(), order.end());
    for (int threads : order)
      for (const PreparedIntegrator& p : integrators) {
        nlohmann::json header = recordHeader("speedup", config.scene, resolution, p.settings);
        header.update({{"threads", threads}, {"spp", config.spp}, {"repeat", repeat}});
        runs.push_back(
            {header, [&, threads, repeat, &p = p](nlohmann::json& record) {
               const uint64_t seed = runSeed(p.settings.type->name, "speedup", config.spp, 0);
               Film film(resolution);
               const TimedRender timed =
                   timedRender(file, *file.sampler, *p.integrator, film, config.spp, threads, seed);
               record.update({
                   {"seed", seed},
                   {"wall_seconds", timed.wallSeconds},
                   {"cpu_seconds", timed.cpuSeconds},
                   {"rays", timed.stats.rays},
               });
               record.update(provenance(machine));
               return fmt::format(
                   "{} threads={} repeat={}: {:.3f} s wall, {:.3f} s CPU, {:.3g} Mrays/s",
                   p.settings.type->name, threads, repeat, timed.wallSeconds, timed.cpuSeconds,
                   timed.stats.rays / std::max(timed.wallSeconds, 1e-9) / 1e6);
             }});
      }
  }
  return executeRuns(group, *std::max_element(config.threads.begin(), config.threads.end()), output,
                     runs, log);
}

}  // namespace verity::studies
