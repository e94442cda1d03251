#include "validation/studies/convergence.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "core/error.h"
#include "core/hash.h"
#include "render/component_images.h"
#include "validation/studies/study_util.h"

namespace verity::studies {

namespace {

std::string convergenceKey(const nlohmann::json& r) {
  return fmt::format("{}|{}x{}|{}|{}|{}|{}|{}|{}", r.value("scene", ""), r.value("width", 0),
                     r.value("height", 0), r.value("integrator", ""), r.value("max_bounces", 0),
                     r.value("threads", 0), r.value("budget_type", ""), r.value("budget", 0.0),
                     r.value("run", 0));
}

std::string speedupKey(const nlohmann::json& r) {
  return fmt::format("{}|{}x{}|{}|{}|{}|{}|{}", r.value("scene", ""), r.value("width", 0),
                     r.value("height", 0), r.value("integrator", ""), r.value("max_bounces", 0),
                     r.value("threads", 0), r.value("spp", 0), r.value("repeat", 0));
}

std::set<std::string> existingKeys(const std::filesystem::path& file, const std::string& study,
                                   std::string (*key)(const nlohmann::json&)) {
  std::set<std::string> keys;
  for (const nlohmann::json& r : readJsonLines(file))
    if (r.value("study", "") == study) keys.insert(key(r));
  return keys;
}

struct Prepared {
  std::string type;
  IntegratorSettings settings;
  std::unique_ptr<Integrator> integrator;
};

std::vector<Prepared> prepareIntegrators(const SceneFile& file,
                                         const std::vector<std::string>& names, int maxBounces) {
  if (names.empty()) throw VerityError("", "--integrators", "no integrator given");
  std::vector<Prepared> out;
  for (const std::string& name : names) {
    Prepared p;
    p.settings = studyIntegrator(file, name, maxBounces);
    p.type = p.settings.type;
    p.integrator = makeIntegrator(p.settings);
    out.push_back(std::move(p));
  }
  return out;
}

std::string strategiesKey(const nlohmann::json& r) {
  return fmt::format("{}|{}x{}|{}|{}", r.value("scene", ""), r.value("width", 0),
                     r.value("height", 0), r.value("max_bounces", 0), r.value("spp", 0));
}

// The fields that say which render a record is of; its key is drawn from them.
nlohmann::json recordHeader(const std::string& study, const std::filesystem::path& scene,
                            const Vector2i& resolution, const IntegratorSettings& settings) {
  return {
      {"study", study},
      {"scene", scene.stem().string()},
      {"scene_file", scene.string()},
      {"width", resolution.x()},
      {"height", resolution.y()},
      {"integrator", settings.type},
      {"max_bounces", settings.maxBounces},
  };
}

// The fields that say where and when a record was measured.
nlohmann::json provenance(const MachineInfo& machine, const std::string& revision) {
  return {
      {"hostname", machine.hostname}, {"cpu_model", machine.cpuModel}, {"cores", machine.cores},
      {"revision", revision},         {"time", timestamp()},
  };
}

// Mean over pixels and channels of a film's pixel means.
double imageMean(const Film& film) {
  double sum = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) sum += double(film.mean(x, y).sum());
  return sum / (3.0 * film.width() * film.height());
}

}  // namespace

StudyProgress runConvergenceStudy(const ConvergenceConfig& config,
                                  const std::function<void(const std::string&)>& log) {
  if (config.budgetType != "spp" && config.budgetType != "time")
    throw VerityError("", "", "the budget is samples per pixel (--spp) or seconds (--time)");
  if (config.budgets.empty()) throw VerityError("", "", "no budget given");
  for (double b : config.budgets)
    if (!(b > 0)) throw VerityError("", "", fmt::format("budgets must be positive, not {}", b));

  const std::string sceneName = config.scene.stem().string();
  const std::filesystem::path referencePath =
      config.reference.empty() ? std::filesystem::path("references") / (sceneName + ".exr")
                               : config.reference;
  if (!std::filesystem::exists(referencePath))
    throw VerityError(referencePath.string(), "",
                      "no reference image: make one with `verity reference` or pass --reference");
  const ImageChannels reference = readExr(referencePath);
  const double referenceOwnRelMse = referenceRelMse(reference);
  auto attribute = [&](const std::string& name) {
    const auto it = reference.attributes.find(name);
    return it == reference.attributes.end() ? std::string() : it->second;
  };

  // The study renders at the reference's resolution unless told otherwise (and then the
  // comparison reports the mismatch).
  const SceneFile file =
      loadStudyScene(config.scene, config.resolution > 0 ? config.resolution : reference.width);
  std::vector<Prepared> integrators =
      prepareIntegrators(file, config.integrators, config.maxBounces);
  const Vector2i resolution = file.scene->camera().resolution();

  const MachineInfo machine = machineInfo();
  const std::string revision = sourceRevision();
  std::set<std::string> done = existingKeys(config.output, "convergence", convergenceKey);
  const double largestBudget = *std::max_element(config.budgets.begin(), config.budgets.end());
  const std::filesystem::path imageDir =
      config.output.parent_path() / (config.output.stem().string() + "-images");

  // Thread count 0 ("all cores") is recorded as the count it means.
  std::vector<int> threadCounts = config.threads;
  for (int& t : threadCounts)
    if (t <= 0) t = std::max(1, machine.cores);

  StudyProgress progress;
  progress.total =
      int(config.threads.size() * config.runs * config.budgets.size() * integrators.size());
  for (size_t ti = 0; ti < config.threads.size(); ++ti)
    for (int run = 0; run < config.runs; ++run)
      for (double budget : config.budgets)
        for (const Prepared& p : integrators) {
          nlohmann::json record = recordHeader("convergence", config.scene, resolution, p.settings);
          record.update({
              {"threads", threadCounts[ti]},
              {"budget_type", config.budgetType},
              {"budget", budget},
              {"run", run},
          });
          if (done.count(convergenceKey(record))) {
            ++progress.skipped;
            continue;
          }
          const uint64_t seed = runSeed(p.type, config.budgetType, budget, run);
          Film film(resolution);
          const bool byTime = config.budgetType == "time";
          const TimedRender timed =
              timedRender(file, *p.integrator, film, byTime ? 0 : int(std::lround(budget)),
                          threadCounts[ti], seed, byTime ? budget : 0);
          const ErrorStats error = compareToReference(film, reference);
          record.update({
              {"seed", seed},
              {"spp", timed.stats.passes},
              {"wall_seconds", timed.wallSeconds},
              {"cpu_seconds", timed.cpuSeconds},
              {"rays", timed.stats.rays},
              {"invalid_samples", timed.stats.invalidSamples},
              {"rel_mse", error.relMse},
              {"rel_mse_epsilon", kRelEpsilon},
              {"rel_variance", error.relVariance},
              {"mean_variance", error.meanVariance},
              {"efficiency", 1.0 / (error.relMse * timed.wallSeconds)},
              {"reference", referencePath.string()},
              {"reference_spp", attribute("verity:spp")},
              {"reference_integrator", attribute("verity:integrator")},
              {"reference_rel_mse", referenceOwnRelMse},
          });
          record.update(provenance(machine, revision));
          if (config.errorImages && ti == 0 && run == 0 && budget == largestBudget) {
            std::filesystem::create_directories(imageDir);
            const std::filesystem::path npy =
                imageDir / fmt::format("{}_{}_{}{}.npy", sceneName, p.type, budget,
                                       config.budgetType == "spp" ? "spp" : "s");
            writeNpy(npy, relativeErrorImage(film, reference), film.width(), film.height());
            record["error_image"] =
                std::filesystem::relative(npy, config.output.parent_path().empty()
                                                   ? std::filesystem::path(".")
                                                   : config.output.parent_path())
                    .string();
          }
          appendJsonLine(config.output, record);
          done.insert(convergenceKey(record));
          ++progress.done;
          if (log)
            log(
                fmt::format("[{}/{}] {} threads={} {}={} run={}: {} spp, {:.3f} s wall, {:.3f} s "
                            "CPU, relMSE {:.4g}",
                            progress.done + progress.skipped, progress.total, p.type,
                            threadCounts[ti], config.budgetType, budget, run, timed.stats.passes,
                            timed.wallSeconds, timed.cpuSeconds, error.relMse));
        }
  return progress;
}

StudyProgress runSpeedupStudy(const SpeedupConfig& config,
                              const std::function<void(const std::string&)>& log) {
  if (config.threads.empty()) throw VerityError("", "--threads", "no thread count given");
  const SceneFile file = loadStudyScene(config.scene, config.resolution);
  std::vector<Prepared> integrators =
      prepareIntegrators(file, config.integrators, config.maxBounces);
  const Vector2i resolution = file.scene->camera().resolution();
  const MachineInfo machine = machineInfo();
  const std::string revision = sourceRevision();
  std::set<std::string> done = existingKeys(config.output, "speedup", speedupKey);

  StudyProgress progress;
  progress.total = int(config.repeats * integrators.size() * config.threads.size());
  for (int repeat = 0; repeat < config.repeats; ++repeat) {
    std::vector<int> order = config.threads;
    if (repeat % 2) std::reverse(order.begin(), order.end());
    for (int threads : order)
      for (const Prepared& p : integrators) {
        nlohmann::json record = recordHeader("speedup", config.scene, resolution, p.settings);
        record.update({{"threads", threads}, {"spp", config.spp}, {"repeat", repeat}});
        if (done.count(speedupKey(record))) {
          ++progress.skipped;
          continue;
        }
        const uint64_t seed = runSeed(p.type, "speedup", config.spp, 0);
        Film film(resolution);
        const TimedRender timed = timedRender(file, *p.integrator, film, config.spp, threads, seed);
        record.update({
            {"seed", seed},
            {"wall_seconds", timed.wallSeconds},
            {"cpu_seconds", timed.cpuSeconds},
            {"rays", timed.stats.rays},
        });
        record.update(provenance(machine, revision));
        appendJsonLine(config.output, record);
        done.insert(speedupKey(record));
        ++progress.done;
        if (log)
          log(
              fmt::format("[{}/{}] {} threads={} repeat={}: {:.3f} s wall, {:.3f} s CPU, {:.3g} "
                          "Mrays/s",
                          progress.done + progress.skipped, progress.total, p.type, threads, repeat,
                          timed.wallSeconds, timed.cpuSeconds,
                          timed.stats.rays / std::max(timed.wallSeconds, 1e-9) / 1e6));
      }
  }
  return progress;
}

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
  if (existingKeys(config.output, "strategies", strategiesKey).count(strategiesKey(record))) {
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
  appendJsonLine(config.output, record);
  progress.done = 1;
  if (log)
    log(fmt::format("bdpt strategies, {} spp, max bounces {}: {:.3f} s wall, {} strategies",
                    config.spp, settings.maxBounces, timed.wallSeconds, strategies.size()));
  return progress;
}

}  // namespace verity::studies
