#include "validation/studies/strategies.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "film/image_io.h"
#include "render/component_images.h"
#include "validation/studies/seeds.h"
#include "validation/studies/study_scene.h"
#include "validation/studies/timed_render.h"

namespace verity::studies {

namespace {

std::string strategiesKey(const nlohmann::json& r) {
  return fmt::format("{}|{}x{}|{}|{}", r.value("scene", ""), r.value("width", 0),
                     r.value("height", 0), r.value("max_bounces", 0), r.value("spp", 0));
}

// Mean over pixels and channels of a film's pixel means.
double imageMean(const Film& film) {
  double sum = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) sum += double(film.mean(x, y).sum());
  return sum / (3.0 * film.width() * film.height());
}

}  // namespace

StudyProgress runStrategiesStudy(const StrategiesConfig& config,
                                 const std::function<void(const std::string&)>& log) {
  std::optional<ImageChannels> reference;
  if (!config.reference.empty()) reference = readExr(config.reference);
  const SceneFile file = loadStudyScene(config.scene, config.resolution > 0 ? config.resolution
                                                      : reference           ? reference->width
                                                                            : 0);
  const IntegratorSettings settings = studyIntegrator(file, "bdpt", config.maxBounces);
  const auto integrator = makeIntegrator(settings);
  const Vector2i resolution = file.scene->camera().resolution();
  const int threads = config.threads > 0 ? config.threads : std::max(1, machineInfo().cores);

  nlohmann::json record = recordHeader("strategies", config.scene, resolution, settings);
  record["spp"] = config.spp;
  StudyProgress progress;
  progress.total = 1;
  StudyOutput output(config.output, "strategies", strategiesKey);
  if (output.has(record)) {
    progress.skipped = 1;
    return progress;
  }
  ComponentImages components(
      ComponentLayout(ComponentLayout::Kind::Strategies, settings.maxBounces), resolution);
  const uint64_t seed = runSeed(settings.type, "strategies", config.spp, 0);
  Film film(resolution);
  const TimedRender timed =
      timedRender(file, *integrator, film, config.spp, threads, seed, 0, &components);
  const double total = imageMean(film);
  nlohmann::json strategies = nlohmann::json::array();
  const ComponentLayout& layout = components.layout();
  for (int i = 0; i < layout.size(); ++i) {
    const ComponentLayout::Component& c = layout[i];
    if (!c.weighted) continue;
    const double mean = imageMean(components.film(i));
    strategies.push_back({{"s", c.s},
                          {"t", c.t},
                          {"bounces", c.bounces},
                          {"mean", mean},
                          {"share", total > 0 ? mean / total : 0.0}});
  }
  const MachineInfo machine = machineInfo();
  record.update({{"threads", threads},
                 {"seed", seed},
                 {"wall_seconds", timed.wallSeconds},
                 {"cpu_seconds", timed.cpuSeconds},
                 {"invalid_samples", timed.stats.invalidSamples},
                 {"image_mean", total},
                 {"strategies", strategies}});
  record.update(provenance(machine, sourceRevision()));
  if (reference) {
    // The share of the full image (the reference's max bounces) that paths longer than
    // max_bounces carry, which no strategy here sees.
    double sum = 0;
    for (const char* c : {"R", "G", "B"})
      for (float v : reference->planes.at(c)) sum += std::isfinite(v) ? v : 0;
    const double full = sum / (3.0 * reference->width * reference->height);
    const auto it = reference->attributes.find("verity:max_bounces");
    record["reference"] = config.reference.string();
    record["reference_mean"] = full;
    record["reference_max_bounces"] = it == reference->attributes.end() ? "" : it->second;
    record["share_beyond_max_bounces"] = full > 0 ? 1 - total / full : 0.0;
  }
  output.append(record);
  progress.done = 1;
  if (log)
    log(fmt::format("bdpt strategies, {} spp, max bounces {}: {:.3f} s wall, {} strategies",
                    config.spp, settings.maxBounces, timed.wallSeconds, strategies.size()));
  return progress;
}

}  // namespace verity::studies
