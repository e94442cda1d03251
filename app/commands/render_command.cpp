#include "commands/render_command.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>

#include "cli/number_options.h"
#include "cli/output_paths.h"
#include "cli/seed_option.h"
#include "cli/subcommand.h"
#include "commands/component_output.h"
#include "distributed/distributed_render.h"
#include "film/image_io.h"
#include "integrators/integrator_registry.h"
#include "integrators/integrator_settings.h"
#include "integrators/strategy_explanation.h"
#include "loader/scene_at_width.h"
#include "render/interrupt.h"
#include "render/renderer.h"
#include "sampling/sampler.h"
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
  int rrDepth = 0;  // 0: the scene's
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

int run(const RenderArgs& args, const ProcessGroup& group) {
  SceneFile file = loadSceneAtWidth(args.scene, args.resolution);
  if (group.isRoot())
    for (const VerityError& warning : file.warnings)
      fmt::print(stderr, "verity: warning: {}\n", warning.what());
  if (args.strict && !file.warnings.empty())
    throw VerityError(
        args.scene, "",
        fmt::format("{} warning(s), and --strict makes them errors", file.warnings.size()));
  IntegratorSettings settings =
      overrideIntegrator(file.integrator, args.integrator, args.maxBounces, "--integrator");
  if (args.rrDepth > 0) {
    if (!declaresKey(*findIntegratorType(settings.type), "rr_depth"))
      throw VerityError("", "--rr-depth",
                        "the integrator \"" + settings.type + "\" has no Russian roulette");
    settings.rrDepth = args.rrDepth;
  }
  if (args.explain) {
    if (!group.isRoot()) return 0;
    fmt::print("{}", file.scene->summary().explain());
    fmt::print("integrator: {} (max_bounces {})\n", settings.type, settings.maxBounces);
    if (const IntegratorType* type = findIntegratorType(settings.type))
      fmt::print("{}", explainStrategies(*type, file.scene->summary()));
    return 0;
  }

  std::vector<std::filesystem::path> outputs;
  if (args.output.empty()) {
    outputs = {file.name + ".exr", file.name + ".png"};
  } else {
    const std::string ext = lowerExtension(args.output);
    if (ext != ".exr" && ext != ".png")
      throw VerityError("", "-o", "the output must end in .exr or .png: \"" + args.output + "\"");
    if (args.variance && ext == ".png")
      throw VerityError("", "--variance",
                        "the variance channels need an EXR output; a PNG holds only colour (\"" +
                            args.output + "\")");
    outputs = {args.output};
  }

  if (!args.sampler.empty()) {
    std::unique_ptr<Sampler> sampler = makeSampler(args.sampler, "--sampler");
    sampler->setSamplesPerPixel(file.sampler->samplesPerPixel());
    if (args.variance && !sampler->samplesAreIndependent())
      throw VerityError("", "--sampler",
                        "the variance channels (--variance) estimate a variance from the "
                        "spread of each pixel's samples, which only independent samples allow; "
                        "sampler \"" +
                            args.sampler + "\" correlates them");
    file.sampler = std::move(sampler);
  }
  if (args.variance)
    requireIndependentSamples(*file.sampler, args.scene, "the variance channels (--variance)");
  if (group.isRoot())
    for (const auto& out : outputs) prepareOutputFile(out, "-o");

  const Vector2i& resolution = file.scene->camera().resolution();
  const bool splitsStrategies = !args.strategies.empty();
  const std::string componentOption = splitsStrategies ? "--strategies" : "--path-lengths";
  const std::filesystem::path componentDir = splitsStrategies ? args.strategies : args.pathLengths;
  std::unique_ptr<ComponentImages> components;
  if (!componentDir.empty() && group.distributed())
    throw VerityError("", componentOption,
                      fmt::format("component images are rendered by one process; run without "
                                  "mpirun (this job has {} ranks)",
                                  group.size()));
  if (!componentDir.empty())
    components = makeComponentImages(componentOption, settings.type, settings.maxBounces,
                                     resolution, componentDir);

  const auto integrator = makeIntegrator(settings);
  Film film(resolution);
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

  ImageChannels image = filmChannels(film, args.variance);
  image.attributes["verity:scene"] = args.scene;
  image.attributes["verity:integrator"] = settings.type;
  image.attributes["verity:max_bounces"] = std::to_string(settings.maxBounces);
  image.attributes["verity:spp"] = std::to_string(stats.passes);
  image.attributes["verity:seed"] = std::to_string(args.seed);
  if (group.distributed())
    image.attributes["verity:processes"] =
        fmt::format("{} MPI ranks, {} threads each; rank 0 on {}", group.size(), options.threads,
                    group.hostName());
  if (stats.interrupted)
    image.attributes["verity:partial"] = fmt::format("interrupted after {} of {} samples per pixel",
                                                     stats.passes, options.samplesPerPixel);
  for (const auto& out : outputs) writeImage(out, image);
  if (components) {
    const RenderRecord record{args.scene,   settings.type, settings.maxBounces,
                              stats.passes, args.seed,     stats.interrupted};
    writeComponentImages(componentDir, *components, record, image.attributes);
  }

  const double seconds = std::max(stats.seconds, 1e-9);
  fmt::print(stderr,
             "{}: {} spp, {}, {:.2f} s, {:.3g} samples/s, {:.3g} Mrays/s, {} invalid samples{}{}\n",
             file.name, stats.passes, settings.type, stats.seconds, stats.samples / seconds,
             stats.rays / seconds / 1e6, stats.invalidSamples,
             stats.invalidSamples ? " (excluded from the average)" : "",
             group.distributed() ? fmt::format(", {} ranks × {} thread{}", group.size(),
                                               options.threads, options.threads == 1 ? "" : "s")
                                 : "");
  if (stats.tracedNoRays)
    fmt::print(stderr,
               "the scene has no emitter and a black background: the image is black and "
               "no ray was traced\n");
  for (const auto& out : outputs) fmt::print(stderr, "wrote {}\n", out.string());
  if (components)
    fmt::print(stderr, "wrote {} images and manifest.json to {}\n", components->layout().size(),
               componentDir.string());
  if (stats.interrupted) {
    fmt::print(stderr,
               "interrupted: the image is PARTIAL, {} of {} samples per pixel (every pixel has "
               "the same count)\n",
               stats.passes, options.samplesPerPixel);
    return 130;
  }
  return 0;
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
  cmd->add_option("--threads", args->threads,
                  "Worker threads per process; 0: all cores (under mpirun, the host's cores "
                  "shared among its ranks)")
      ->check(wholeNumber(0));
  addSeedOption(cmd, args->seed, "Seed of the render's random numbers (0 to 2^64 - 1)")
      ->default_str("0");
  cmd->add_option("--integrator", args->integrator, integratorTypeList())
      ->default_str("the scene's");
  cmd->add_option("--sampler", args->sampler,
                  "Sampler, its keys at their defaults: " + samplerTypeList())
      ->default_str("the scene's");
  cmd->add_option("--max-bounces", args->maxBounces,
                  "Maximum scattering events per path (0: emitters seen directly)")
      ->default_str("the scene's")
      ->check(wholeNumber(0, kMaxBouncesLimit));
  cmd->add_option("--rr-depth", args->rrDepth,
                  "Scattering event after which Russian roulette first decides whether a path "
                  "goes on (the integrator's \"rr_depth\")")
      ->default_str("the scene's")
      ->check(wholeNumber(1));
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
