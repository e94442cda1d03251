#include "commands/render_command.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>

#include "cli/exit_status.h"
#include "cli/max_bounces_option.h"
#include "cli/number_options.h"
#include "cli/output_paths.h"
#include "cli/roulette_options.h"
#include "cli/seed_option.h"
#include "cli/subcommand.h"
#include "cli/threads_option.h"
#include "commands/component_output.h"
#include "distributed/distributed_render.h"
#include "film/image_io.h"
#include "integrators/integrator_registry.h"
#include "integrators/integrator_settings.h"
#include "integrators/strategy_explanation.h"
#include "loader/scene_loader.h"
#include "render/interrupt.h"
#include "render/renderer.h"
#include "sampling/sampler_registry.h"

namespace verity {

namespace {

struct RenderArgs {
  std::string scene;
  int spp = 0;         // 0: the scene's
  int resolution = 0;  // image width; 0: the scene's
  int threads = 0;
  uint64_t seed = 0;
  std::string integrator;
  std::string sampler;  // a registry type with its keys at their defaults; empty: the scene's
  int maxBounces = -1;
  int rrDepth = 0;        // 0: the scene's
  float rrThreshold = 0;  // 0: the scene's
  std::string output;
  bool variance = false;
  bool explain = false;
  bool strict = false;      // the scene's warnings are errors
  std::string strategies;   // directory for per-strategy images (bdpt)
  std::string pathLengths;  // directory for per-path-length images
};

std::string lowerExtension(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// Written under a temporary name and renamed when whole, so that a job killed while writing
// (a rank of an MPI job dying takes rank 0 with it) leaves no file that looks complete.
void writeImage(const std::filesystem::path& out, const ImageChannels& image) {
  const std::filesystem::path writing = out.string() + ".writing";
  if (lowerExtension(out) == ".exr")
    writeExr(writing, image);
  else
    writePng(writing, image);
  std::filesystem::rename(writing, out);
}

// The command line's changes to the scene, applied as it is loaded.
SceneOverrides sceneOverrides(const RenderArgs& args) {
  SceneOverrides overrides;
  overrides.width = args.resolution;
  if (!args.integrator.empty())
    overrides.integrator.type = &integratorTypeNamed(args.integrator, "--integrator");
  overrides.integrator.maxBounces = args.maxBounces;
  overrides.integrator.rrDepth = args.rrDepth;
  overrides.integrator.rrThreshold = args.rrThreshold;
  overrides.sampler = args.sampler;
  return overrides;
}

// The images to write: -o, else <scene name>.exr and .png here.
std::vector<std::filesystem::path> outputPaths(const RenderArgs& args) {
  if (args.output.empty()) {
    const std::string name = std::filesystem::path(args.scene).stem().string();
    return {name + ".exr", name + ".png"};
  }
  const std::string ext = lowerExtension(args.output);
  if (ext != ".exr" && ext != ".png")
    throw VerityError("", "-o", "the output must end in .exr or .png: \"" + args.output + "\"");
  if (args.variance && ext == ".png")
    throw VerityError("", "--variance",
                      "the variance channels need an EXR output; a PNG holds only colour (\"" +
                          args.output + "\")");
  return {args.output};
}

// Prints the loader's warnings; with --strict they are an error.
void reportWarnings(const SceneFile& file, const RenderArgs& args, const ProcessGroup& group) {
  if (group.isRoot())
    for (const VerityError& warning : file.warnings)
      fmt::print(stderr, "verity: warning: {}\n", warning.what());
  if (args.strict && !file.warnings.empty())
    throw VerityError(
        args.scene, "",
        fmt::format("{} warning(s), and --strict makes them errors", file.warnings.size()));
}

// --variance estimates each pixel's variance from the spread of its samples, which only
// independent samples allow.
void requireVarianceSamples(const SceneFile& file, const RenderArgs& args) {
  if (!args.variance || file.sampler->samplesAreIndependent()) return;
  const bool given = !args.sampler.empty();
  throw VerityError(given ? "" : args.scene, given ? "--sampler" : "sampler.type",
                    "the variance channels (--variance) estimate a variance from the spread of "
                    "each pixel's samples, which only independent samples allow; this sampler "
                    "correlates them (use the independent sampler)");
}

void explain(const SceneFile& file) {
  const IntegratorSettings& settings = file.integrator;
  fmt::print("{}", file.scene->summary().explain());
  fmt::print("integrator: {} (max_bounces {})\n", settings.type->name, settings.maxBounces);
  fmt::print("{}", explainStrategies(*settings.type, file.scene->summary()));
}

// The per-strategy or per-path-length images --strategies or --path-lengths asks for, or null.
struct ComponentRequest {
  std::string option;
  std::filesystem::path dir;
};

ComponentRequest componentRequest(const RenderArgs& args) {
  if (!args.strategies.empty()) return {"--strategies", args.strategies};
  if (!args.pathLengths.empty()) return {"--path-lengths", args.pathLengths};
  return {};
}

std::unique_ptr<ComponentImages> componentImages(const ComponentRequest& request,
                                                 const SceneFile& file, const ProcessGroup& group) {
  if (request.dir.empty()) return nullptr;
  if (group.distributed())
    throw VerityError("", request.option,
                      fmt::format("component images are rendered by one process; run without "
                                  "mpirun (this job has {} ranks)",
                                  group.size()));
  return makeComponentImages(request.option, file.integrator, file.scene->camera().resolution(),
                             request.dir);
}

// The image's channels and the attributes that record how it was made.
ImageChannels renderedImage(const Film& film, const RenderArgs& args, const SceneFile& file,
                            const RenderStats& stats, const RenderOptions& options,
                            const ProcessGroup& group) {
  ImageChannels image = filmChannels(film, args.variance);
  image.attributes["verity:scene"] = args.scene;
  image.attributes["verity:integrator"] = file.integrator.type->name;
  image.attributes["verity:max_bounces"] = std::to_string(file.integrator.maxBounces);
  image.attributes["verity:spp"] = std::to_string(stats.passes);
  image.attributes["verity:seed"] = std::to_string(args.seed);
  if (group.distributed())
    image.attributes["verity:processes"] =
        fmt::format("{} MPI ranks, {} threads each; rank 0 on {}", group.size(), options.threads,
                    group.hostName());
  if (stats.interrupted)
    image.attributes["verity:partial"] = fmt::format("interrupted after {} of {} samples per pixel",
                                                     stats.passes, options.samplesPerPixel);
  return image;
}

void printStats(const SceneFile& file, const RenderStats& stats, const RenderOptions& options,
                const ProcessGroup& group) {
  const double seconds = std::max(stats.seconds, 1e-9);
  fmt::print(stderr,
             "{}: {} spp, {}, {:.2f} s, {:.3g} samples/s, {:.3g} Mrays/s, {} invalid samples{}{}\n",
             file.name, stats.passes, file.integrator.type->name, stats.seconds,
             stats.samples / seconds, stats.rays / seconds / 1e6, stats.invalidSamples,
             stats.invalidSamples ? " (excluded from the average)" : "",
             group.distributed() ? fmt::format(", {} ranks × {} thread{}", group.size(),
                                               options.threads, options.threads == 1 ? "" : "s")
                                 : "");
  if (stats.tracedNoRays)
    fmt::print(stderr,
               "the scene has no emitter and a black background: the image is black and "
               "no ray was traced\n");
}

int run(const RenderArgs& args, const ProcessGroup& group) {
  const std::vector<std::filesystem::path> outputs = outputPaths(args);
  SceneFile file = loadScene(args.scene, sceneOverrides(args));
  reportWarnings(file, args, group);
  if (args.explain) {
    if (group.isRoot()) explain(file);
    return 0;
  }
  requireVarianceSamples(file, args);
  if (group.isRoot())
    for (const auto& out : outputs) prepareOutputFile(out, "-o");
  const ComponentRequest request = componentRequest(args);
  const std::unique_ptr<ComponentImages> components = componentImages(request, file, group);

  const auto integrator = makeIntegrator(file.integrator);
  Film film(file.scene->camera().resolution());
  RenderOptions options;
  options.components = components.get();
  options.samplesPerPixel = args.spp > 0 ? args.spp : file.sampler->samplesPerPixel();
  options.threads = group.threadsPerRank(args.threads);
  options.progress = group.isRoot() && isatty(STDERR_FILENO);
  InterruptGuard interrupt(/*alsoTerminate=*/group.distributed());
  options.cancel = &InterruptGuard::flag();
  file.sampler->setSeed(args.seed);
  const RenderStats stats =
      renderDistributed(group, *file.scene, *integrator, *file.sampler, film, options);
  if (!group.isRoot()) return 0;
  // A hidden hook for the MPI tests: the film's bits, which the image rounds to float.
  if (std::getenv("VERITY_TEST_FILM_DIGEST"))
    fmt::print(stderr, "verity: film digest {:016x}\n", film.digest());

  const ImageChannels image = renderedImage(film, args, file, stats, options, group);
  for (const auto& out : outputs) writeImage(out, image);
  if (components) {
    const RenderRecord record{
        args.scene, file.integrator.type->name, file.integrator.maxBounces, stats.passes,
        args.seed,  stats.interrupted};
    writeComponentImages(request.dir, *components, record, image.attributes);
  }
  printStats(file, stats, options, group);
  for (const auto& out : outputs) fmt::print(stderr, "wrote {}\n", out.string());
  if (components)
    fmt::print(stderr, "wrote {} images and manifest.json to {}\n", components->layout().size(),
               request.dir.string());
  if (!stats.interrupted) return 0;
  fmt::print(stderr,
             "interrupted: the image is PARTIAL, {} of {} samples per pixel (every pixel has "
             "the same count)\n",
             stats.passes, options.samplesPerPixel);
  return kInterruptedStatus;
}

}  // namespace

void addRenderCommand(CLI::App& app, const ProcessGroup& group) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd =
      addSubcommand(app, "render", "Render a DIRT-format JSON scene", MpiUse::SplitsWork, group);
  cmd->add_option("scene", args->scene, "Scene file (.json)")->required();
  cmd->add_option("--spp", args->spp, "Samples per pixel")
      ->default_str("the scene's")
      ->check(wholeNumber(1));
  cmd->add_option("--resolution", args->resolution,
                  "Image width in pixels, the scene's aspect ratio kept")
      ->default_str("the scene's")
      ->check(wholeNumber(1));
  addThreadsOption(cmd, args->threads, MpiUse::SplitsWork);
  addSeedOption(cmd, args->seed, "Seed of the render's random numbers (0 to 2^64 - 1)")
      ->default_str("0");
  cmd->add_option("--integrator", args->integrator, integratorTypeList())
      ->default_str("the scene's");
  cmd->add_option("--sampler", args->sampler,
                  "Sampler, its keys at their defaults: " + samplerTypeList())
      ->default_str("the scene's");
  addMaxBouncesOption(cmd, args->maxBounces);
  addRouletteOptions(cmd, args->rrDepth, args->rrThreshold);
  CLI::Option* output =
      cmd->add_option("-o,--output", args->output,
                      "Output image file, .exr or .png; missing folders are created")
          ->default_str("<scene name>.exr and .png here");
  cmd->add_flag("--variance", args->variance,
                "Add variance.R/G/B (per-sample variance) and samples channels to the EXR");
  auto* strategies = cmd->add_option(
      "--strategies", args->strategies,
      "Folder for the MIS-weighted and unweighted image of every BDPT strategy (s, t) and "
      "a manifest.json (bdpt only; created if missing)");
  CLI::Option* pathLengths =
      cmd->add_option("--path-lengths", args->pathLengths,
                      "Folder for one image per path length (bounces) and a manifest.json "
                      "(created if missing)")
          ->excludes(strategies);
  cmd->add_flag("--strict", args->strict,
                "Refuse a scene the loader warns about (an albedo above 1, a light emitting 0)");
  cmd->add_flag("--explain", args->explain,
                "Print what the scene calls for (emitters, lobes, textures, strategies) and exit");
  cmd->callback([=, &group] {
    // An empty name given is not the default (which an empty value would otherwise select).
    for (const auto& [option, name] :
         {std::pair{output, "-o"}, std::pair{strategies, "--strategies"},
          std::pair{pathLengths, "--path-lengths"}})
      if (option->count() > 0 && option->as<std::string>().empty())
        throw VerityError("", name, "the name given is empty");
    throw CLI::RuntimeError(run(*args, group));
  });
}

}  // namespace verity
