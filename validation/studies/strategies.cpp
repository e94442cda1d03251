#include "validation/studies/strategies.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/error.h"
#include "render/component_images.h"
#include "sampling/sampler.h"
#include "validation/studies/npy_file.h"
#include "validation/studies/reference_match.h"
#include "validation/studies/relative_error.h"
#include "validation/studies/seeds.h"
#include "validation/studies/strategy_variance.h"
#include "validation/studies/study_scene.h"
#include "validation/studies/timed_render.h"

namespace verity::studies {

namespace {

// What tells one record of the study from another.
struct StrategiesRunKey {
  std::string scene;
  int width, height, maxBounces;
  BudgetType budgetType;
  double budget;
  int run;
  std::string pathTracer;
  auto operator<=>(const StrategiesRunKey&) const = default;
};

StrategiesRunKey strategiesRunKey(const FieldReader& r) {
  const FieldReader pathTracer(r.object("path_tracer"), r.file(), r.where() + ", \"path_tracer\"");
  return {
      r.text("scene"),   r.integer("width"), r.integer("height"), r.integer("max_bounces"),
      readBudgetType(r), r.number("budget"), r.integer("run"),    pathTracer.text("integrator")};
}

// Mean over pixels and channels of a film's pixel means.
double imageMean(const Film& film) {
  double sum = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) sum += double(film.mean(x, y).sum());
  return sum / (3.0 * film.width() * film.height());
}

// A render with its component images, and what the record says of it.
struct ComponentRender {
  std::unique_ptr<ComponentImages> components;
  Film film;
  nlohmann::json record;
};

ComponentRender renderComponents(const SceneFile& file, const Integrator& integrator,
                                 const IntegratorSettings& settings, ComponentLayout::Kind kind,
                                 const StrategiesConfig& config, double budget, int threads,
                                 uint64_t seed) {
  const Vector2i resolution = file.scene->camera().resolution();
  ComponentRender r{
      std::make_unique<ComponentImages>(ComponentLayout(kind, settings.maxBounces), resolution),
      Film(resolution),
      {}};
  const bool byTime = config.budgetType == BudgetType::Time;
  const TimedRender timed =
      timedRender(file, *file.sampler, integrator, r.film, byTime ? 0 : int(std::lround(budget)),
                  threads, seed, byTime ? budget : 0, r.components.get());
  r.record = {{"integrator", settings.type->name}, {"seed", seed},
              {"spp", timed.stats.passes},         {"wall_seconds", timed.wallSeconds},
              {"cpu_seconds", timed.cpuSeconds},   {"invalid_samples", timed.stats.invalidSamples}};
  return r;
}

// The weighted strategy images, in the record's order, as (height, width, RGB) planes.
void writeStrategyImages(const std::filesystem::path& npy, const ComponentImages& components) {
  const ComponentLayout& layout = components.layout();
  std::vector<float> data;
  size_t images = 0;
  for (int i = 0; i < layout.size(); ++i) {
    if (!layout[i].weighted) continue;
    const Film& film = components.film(i);
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < film.width(); ++x) {
        const Color3 m = film.mean(x, y);
        for (int c = 0; c < 3; ++c) data.push_back(m[c]);
      }
    ++images;
  }
  const Film& first = components.film(0);
  writeHalfNpy(npy, data, {images, size_t(first.height()), size_t(first.width()), 3});
}

}  // namespace

StudyProgress runStrategiesStudy(const StrategiesConfig& config,
                                 const std::function<void(const std::string&)>& log) {
  checkBudgets(config.budgetType, config.budgets);

  std::optional<ImageChannels> reference;
  if (!config.reference.empty()) reference = readExr(config.reference);
  const SceneFile file =
      loadScene(config.scene, SceneOverrides::atWidth(config.resolution > 0 ? config.resolution
                                                      : reference           ? reference->width
                                                                            : 0));
  requireIndependentSamples(*file.sampler, config.scene,
                            "the strategies study's variance columns (rel_variance_*)");
  const IntegratorSettings settings = studyIntegrator(file, "bdpt", config.maxBounces);
  const IntegratorSettings ptSettings =
      studyIntegrator(file, config.pathTracer, settings.maxBounces);
  const auto integrator = makeIntegrator(settings);
  const auto pathTracer = makeIntegrator(ptSettings);
  const Vector2i resolution = file.scene->camera().resolution();
  if (reference)
    checkReferenceMatches(config.reference, *reference, config.scene, resolution,
                          config.resolution > 0, config.force, log);
  const MachineInfo machine = machineInfo();
  const int threads = config.threads > 0 ? config.threads : std::max(1, machine.cores);
  const double largestBudget = *std::max_element(config.budgets.begin(), config.budgets.end());
  const std::filesystem::path imageDir =
      config.output.parent_path() / (config.output.stem().string() + "-images");
  // spp budgets keep the seed of the one-render study, so its records stay reproducible.
  const std::string seedKind =
      config.budgetType == BudgetType::Spp ? "strategies" : "strategies time";

  // The share of the full image (the reference's max bounces) that paths longer than
  // max_bounces carry, which no strategy here sees.
  double referenceMean = 0;
  if (reference) {
    double sum = 0;
    for (const char* c : {"R", "G", "B"})
      for (float v : reference->planes.at(c)) sum += std::isfinite(v) ? v : 0;
    referenceMean = sum / (3.0 * reference->width * reference->height);
  }

  KeyedStudyOutput output(config.output, "strategies", strategiesRunKey);
  output.repairTruncatedLine(log);
  StudyProgress progress;
  progress.total = int(config.runs * config.budgets.size());
  for (int run = 0; run < config.runs; ++run)
    for (double budget : config.budgets) {
      nlohmann::json record = recordHeader("strategies", config.scene, resolution, settings);
      record.update({{"budget_type", budgetTypeName(config.budgetType)},
                     {"budget", budget},
                     {"run", run},
                     {"path_tracer", {{"integrator", ptSettings.type->name}}}});
      if (output.has(record)) {
        ++progress.skipped;
        continue;
      }
      const ComponentRender strategies =
          renderComponents(file, *integrator, settings, ComponentLayout::Kind::Strategies, config,
                           budget, threads, runSeed(settings.type->name, seedKind, budget, run));
      const ComponentRender lengths = renderComponents(
          file, *integrator, settings, ComponentLayout::Kind::PathLengths, config, budget, threads,
          runSeed(settings.type->name + " path lengths", seedKind, budget, run));
      const ComponentRender traced = renderComponents(
          file, *pathTracer, ptSettings, ComponentLayout::Kind::PathLengths, config, budget,
          threads, runSeed(ptSettings.type->name, seedKind, budget, run));

      // r_k: BDPT's length-k image from its own render, independent of the strategies'; all
      // of length k are averaged over the pixels where r_k is non-zero. (Not over those where
      // a strategy's own image is: for a strategy that rarely finds a path, such as (0, 3)
      // hitting a small light, that keeps the pixels it happened to reach and biases its mean
      // and variance upward, by more at smaller budgets.)
      auto lengthImage = [&](int k) -> const Film& { return lengths.components->film(k); };
      std::vector<std::vector<uint8_t>> lit;
      for (int k = 0; k <= settings.maxBounces; ++k) lit.push_back(nonZeroPixels(lengthImage(k)));
      const double total = imageMean(strategies.film);
      nlohmann::json strategyList = nlohmann::json::array();
      const ComponentLayout& layout = strategies.components->layout();
      for (int i = 0; i < layout.size(); ++i) {
        const ComponentLayout::Component& c = layout[i];
        if (!c.weighted) continue;
        const Film& weighted = strategies.components->film(i);
        const Film& unweighted = strategies.components->film(layout.strategyIndex(c.s, c.t, false));
        const Film& rk = lengthImage(c.bounces);
        const std::vector<uint8_t>& pixels = lit[c.bounces];
        const ComponentVariance w = componentVariance(weighted, rk, pixels);
        const ComponentVariance u = componentVariance(unweighted, rk, pixels);
        const ComponentVariance r = componentVariance(rk, rk, pixels);
        // The pixels of r_k the strategy reached in this render: its coverage, to its samples.
        const std::vector<uint8_t> reached = nonZeroPixels(unweighted);
        size_t reachedPixels = 0;
        for (size_t p = 0; p < reached.size(); ++p) reachedPixels += reached[p] && pixels[p];
        const double mean = imageMean(weighted);
        strategyList.push_back({{"s", c.s},
                                {"t", c.t},
                                {"bounces", c.bounces},
                                {"mean", mean},
                                {"share", total > 0 ? mean / total : 0.0},
                                {"pixels", u.pixels},
                                {"pixels_reached", reachedPixels},
                                {"rel_variance_weighted", w.relVariance},
                                {"rel_variance_unweighted", u.relVariance},
                                {"unweighted_mean", u.mean},
                                {"unweighted_standard_error", u.standardError},
                                {"length_mean", r.mean},
                                {"length_standard_error", r.standardError}});
      }
      nlohmann::json lengthList = nlohmann::json::array();
      for (int k = 0; k <= settings.maxBounces; ++k) {
        const ComponentVariance b = componentVariance(lengthImage(k), lengthImage(k), lit[k]);
        const ComponentVariance p =
            componentVariance(traced.components->film(k), lengthImage(k), lit[k]);
        lengthList.push_back({{"bounces", k},
                              {"pixels", b.pixels},
                              {"mean", b.mean},
                              {"rel_variance", b.relVariance},
                              {"path_tracer_mean", p.mean},
                              {"path_tracer_rel_variance", p.relVariance}});
      }

      record.update(strategies.record);
      record.update({{"threads", threads},
                     {"image_mean", total},
                     {"rel_mse_epsilon", kRelEpsilon},
                     {"strategies", strategyList},
                     {"lengths", lengthList},
                     {"bdpt_lengths", lengths.record},
                     {"path_tracer", traced.record}});
      record.update(provenance(machine));
      if (reference) {
        const auto it = reference->attributes.find("verity:max_bounces");
        record["reference"] = config.reference.string();
        record["reference_mean"] = referenceMean;
        record["reference_max_bounces"] = it == reference->attributes.end() ? "" : it->second;
        record["share_beyond_max_bounces"] = referenceMean > 0 ? 1 - total / referenceMean : 0.0;
      }
      if (config.images && run == 0 && budget == largestBudget) {
        std::filesystem::create_directories(imageDir);
        const std::filesystem::path npy =
            imageDir / fmt::format("{}_strategies_{}{}.npy", config.scene.stem().string(), budget,
                                   budgetUnit(config.budgetType));
        writeStrategyImages(npy, *strategies.components);
        record["strategy_images"] =
            std::filesystem::relative(npy, config.output.parent_path().empty()
                                               ? std::filesystem::path(".")
                                               : config.output.parent_path())
                .string();
      }
      output.append(record);
      ++progress.done;
      if (log)
        log(fmt::format(
            "[{}/{}] strategies {}={} run={}, max bounces {}: bdpt {} spp {:.3f} s (strategies), "
            "{} spp {:.3f} s (path lengths); {} {} spp {:.3f} s",
            progress.done + progress.skipped, progress.total, budgetTypeName(config.budgetType),
            budget, run, settings.maxBounces, strategies.record["spp"].get<int>(),
            strategies.record["wall_seconds"].get<double>(), lengths.record["spp"].get<int>(),
            lengths.record["wall_seconds"].get<double>(), ptSettings.type->name,
            traced.record["spp"].get<int>(), traced.record["wall_seconds"].get<double>()));
    }
  return progress;
}

}  // namespace verity::studies
