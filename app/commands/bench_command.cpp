#include "commands/bench_command.h"

#include <fmt/format.h>
#include <sys/resource.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <numeric>

#include "cli/max_bounces_option.h"
#include "cli/number_options.h"
#include "cli/subcommand.h"
#include "cli/threads_option.h"
#include "core/error.h"
#include "film/image_io.h"
#include "integrators/integrator_registry.h"
#include "integrators/integrator_settings.h"
#include "render/renderer.h"
#include "sampling/independent_sampler.h"
#include "sampling/sampler_registry.h"
#include "sampling/warp.h"
#include "validation/studies/fit.h"
#include "validation/studies/relative_error.h"
#include "validation/studies/seeds.h"
#include "validation/studies/study_sampler.h"
#include "validation/studies/study_scene.h"
#include "validation/studies/timed_render.h"

namespace verity {

namespace {

using studies::median;

struct BenchArgs {
  std::string scene;
  int spp = 8;
  int resolution = 0;
  int repeats = 3;
  bool bdpt = false;      // time BDPT against the path tracer instead
  std::string reference;  // efficiency against this image instead
  std::vector<std::string> integrators = {"path_tracer_nee", "path_tracer_mis", "bdpt"};
  int threads = 0;
  int maxBounces = -1;  // -1: the scene's
  // Russian roulette depths compared with --reference, each with every integrator; empty: the
  // scene's (or the default).
  std::vector<int> rrDepths;
  std::vector<float> rrThresholds;  // likewise, each with every depth
  // Samplers (registry names) compared with --reference, each with every integrator; empty: the
  // scene's.
  std::vector<std::string> samplers;
};

double seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

// Incoherent rays: random origins inside the scene's bounds, uniform random directions,
// closest hit only. Generation is included, as in the engineering notes' measurement.
double rawRaysPerSecond(const Scene& scene, uint64_t rays) {
  IndependentSampler sampler;
  sampler.setSeed(99);
  sampler.startPixelSample(Point2i(0, 0), 0);
  const Bounds3f& b = scene.bounds();
  const Vector3f extent = b.hi - b.lo;
  uint64_t hits = 0;
  const auto start = std::chrono::steady_clock::now();
  for (uint64_t i = 0; i < rays; ++i) {
    const Point2f u = sampler.next2D();
    const Point3f o = b.lo + extent.cwiseProduct(Vector3f(u.x(), u.y(), sampler.next1D()));
    SurfaceInteraction si;
    hits += scene.intersect(Ray(o, warp::squareToUniformSphere(sampler.next2D())), si);
  }
  const double t = seconds(std::chrono::steady_clock::now() - start);
  if (hits == 0) fmt::print(stderr, "warning: no random ray hit the scene\n");
  return rays / t;
}

RenderStats timedRender(const SceneFile& file, const Integrator& integrator, int spp, int threads,
                        const Vector2i& resolution) {
  Film film(resolution);
  RenderOptions options;
  options.samplesPerPixel = spp;
  options.threads = threads;
  return render(*file.scene, integrator, *file.sampler, film, options);
}

// The rays one single-threaded sample of `integrator` traces, on average, logged from a render
// at 1 spp (independent samples, so any sample count gives the same mix of rays).
struct SampleRays {
  RayLog log;
  uint64_t samples = 0;
};

void logSampleRays(const SceneFile& file, const Integrator& integrator, const Vector2i& resolution,
                   SampleRays& out) {
  file.scene->setRayLog(&out.log);
  out.samples = timedRender(file, integrator, 1, 1, resolution).samples;
  file.scene->setRayLog(nullptr);
}

// Time per sample of the logged rays traced again on their own, in order, on one thread: the
// cost of the ray queries apart from the integrator's other work.
double replayedSecondsPerSample(const Scene& scene, const SampleRays& rays) {
  const auto start = std::chrono::steady_clock::now();
  for (const LoggedRay& r : rays.log.rays()) {
    SurfaceInteraction si;
    if (r.shadow)
      scene.occluded(r.ray);
    else
      scene.intersect(r.ray, si);
  }
  return seconds(std::chrono::steady_clock::now() - start) / rays.samples;
}

// BDPT against the path tracer with next-event estimation: time per sample single-threaded
// (the ratio of each repeat's adjacent pair, so that both see the same machine load) and
// BDPT's speedup at 2 threads.
int runBdpt(const SceneFile& file, const BenchArgs& args) {
  const IntegratorSettings ptSettings =
      studies::studyIntegrator(file, "path_tracer_nee", args.maxBounces);
  const IntegratorSettings bdptSettings = studies::studyIntegrator(file, "bdpt", args.maxBounces);
  const auto pt = makeIntegrator(ptSettings);
  const auto bdpt = makeIntegrator(bdptSettings);
  const Vector2i resolution = file.scene->camera().resolution();
  fmt::print("scene {}: {}×{}, {} spp, max_bounces {}: bdpt vs path_tracer_nee\n", file.name,
             resolution.x(), resolution.y(), args.spp, bdptSettings.maxBounces);
  SampleRays ptLog, bdptLog;
  logSampleRays(file, *pt, resolution, ptLog);
  logSampleRays(file, *bdpt, resolution, bdptLog);
  std::vector<double> ptOne, bdptOne, ratio, speedup, ptRayTime, bdptRayTime, bdptRayRatio;
  double ptRays = 0, bdptRays = 0;  // per sample (the same in every repeat: seeded)
  for (int r = 0; r < args.repeats; ++r) {
    const RenderStats a = timedRender(file, *pt, args.spp, 1, resolution);
    const RenderStats b = timedRender(file, *bdpt, args.spp, 1, resolution);
    const RenderStats b2 = timedRender(file, *bdpt, args.spp, 2, resolution);
    const double ptReplay =
        tbb::task_arena(1).execute([&] { return replayedSecondsPerSample(*file.scene, ptLog); });
    const double bdptReplay =
        tbb::task_arena(1).execute([&] { return replayedSecondsPerSample(*file.scene, bdptLog); });
    ptOne.push_back(a.seconds / a.samples);
    bdptOne.push_back(b.seconds / b.samples);
    ratio.push_back(bdptOne.back() / ptOne.back());
    speedup.push_back(b.seconds / b2.seconds);
    ptRayTime.push_back(ptReplay);
    bdptRayTime.push_back(bdptReplay);
    bdptRayRatio.push_back(bdptReplay / ptOne.back());
    ptRays = double(a.rays) / a.samples;
    bdptRays = double(b.rays) / b.samples;
  }
  fmt::print(
      "path_tracer_nee, 1 thread: {:8.3f} µs/sample  ({:.3f} Msamples/s, {:.2f} rays/sample)\n",
      1e6 * median(ptOne), 1e-6 / median(ptOne), ptRays);
  fmt::print(
      "bdpt, 1 thread:            {:8.3f} µs/sample  ({:.3f} Msamples/s, {:.2f} rays/sample)\n",
      1e6 * median(bdptOne), 1e-6 / median(bdptOne), bdptRays);
  // Time per sample is no yardstick across integrators (BDPT spends more per sample to lose
  // less variance): `--reference` measures efficiency instead.
  fmt::print("bdpt / path_tracer_nee time per sample: {:.2f}x  (compare efficiency: --reference)\n",
             median(ratio));
  // What the rays alone cost bounds the ratio from below, however fast the rest becomes.
  const double ptRayShare = median(ptRayTime) / median(ptOne);
  const double bdptRayShare = median(bdptRayTime) / median(bdptOne);
  fmt::print(
      "rays alone, replayed:   path_tracer_nee {:.3f} µs/sample ({:.0f}% of its time), "
      "bdpt {:.3f} µs/sample ({:.0f}%)\n",
      1e6 * median(ptRayTime), 100 * ptRayShare, 1e6 * median(bdptRayTime), 100 * bdptRayShare);
  fmt::print("bdpt's rays alone / path_tracer_nee's whole sample: {:.2f}x\n", median(bdptRayRatio));
  fmt::print("work besides rays: path_tracer_nee {:.3f} µs/sample, bdpt {:.3f} µs/sample\n",
             1e6 * (median(ptOne) - median(ptRayTime)),
             1e6 * (median(bdptOne) - median(bdptRayTime)));
  fmt::print("bdpt speedup at 2 threads:              {:.2f}x  (target >= 1.9x)\n",
             median(speedup));
  fmt::print("medians of {} alternating repeats\n", args.repeats);
  return 0;
}

// Efficiency 1 / (relMSE · seconds) of each integrator against a reference image (Veach 1997,
// section 2.4): the yardstick that weighs time per sample against variance per sample. Each
// repeat renders every integrator once with its own seed, alternating, so that load changes
// hit all alike; relMSE is the mean over repeats (unbiased for its expectation), seconds the
// median.
int runEfficiency(const SceneFile& file, const BenchArgs& args) {
  const ImageChannels reference = studies::readReference(args.reference);
  const Vector2i resolution = file.scene->camera().resolution();
  if (reference.width != resolution.x() || reference.height != resolution.y())
    throw VerityError(args.reference, "",
                      fmt::format("the reference is {}×{}, the render {}×{}: pass --resolution {}",
                                  reference.width, reference.height, resolution.x(), resolution.y(),
                                  reference.width));
  struct Measured {
    // The integrator, its roulette depth and threshold when --rr-depth and --rr-threshold
    // compare some, and its sampler when --sampler does.
    std::string label;
    IntegratorSettings settings;
    std::unique_ptr<Integrator> integrator;
    const studies::StudySampler* sampler = nullptr;
    std::vector<double> seconds, relMse;
    studies::FireflyShare fireflies;  // summed over the repeats
  };
  const std::vector<studies::StudySampler> samplers =
      studies::prepareSamplers(file, args.samplers, "--sampler");
  std::vector<Measured> measured;
  for (const std::string& name : args.integrators) {
    const IntegratorSettings settings = studies::studyIntegrator(file, name, args.maxBounces);
    const std::vector<int> depths =
        args.rrDepths.empty() ? std::vector<int>{settings.rrDepth} : args.rrDepths;
    const std::vector<float> thresholds =
        args.rrThresholds.empty() ? std::vector<float>{makeRoulette(settings).threshold()}
                                  : args.rrThresholds;
    for (const int depth : depths)
      for (const float threshold : thresholds)
        for (const studies::StudySampler& sampler : samplers) {
          Measured m;
          // --rr-depth and --rr-threshold, checked against the integrator
          IntegratorOverrides roulette;
          roulette.rrDepth = args.rrDepths.empty() ? 0 : depth;
          roulette.rrThreshold = args.rrThresholds.empty() ? 0 : threshold;
          m.settings = overrideIntegrator(settings, roulette);
          m.label = name;
          if (!args.rrDepths.empty()) m.label += fmt::format(" rr_depth {}", depth);
          if (!args.rrThresholds.empty()) m.label += fmt::format(" rr_threshold {}", threshold);
          if (!args.samplers.empty()) m.label += " " + sampler.type;
          m.integrator = makeIntegrator(m.settings);
          m.sampler = &sampler;
          measured.push_back(std::move(m));
        }
  }
  const double referenceRelMse = studies::referenceRelMse(reference);
  std::string samplerNames;
  for (const studies::StudySampler& s : samplers)
    samplerNames += (samplerNames.empty() ? "" : ", ") + s.type;
  fmt::print(
      "scene {}: {}×{}, {} spp, {} threads, sampler {}, against {} (its own relMSE {:.3g})\n",
      file.name, resolution.x(), resolution.y(), args.spp, args.threads, samplerNames,
      args.reference, referenceRelMse);
  for (int r = 0; r < args.repeats; ++r)
    for (Measured& m : measured) {
      Film film(resolution);
      film.trackMaxima();
      const uint64_t seed =
          studies::runSeed(m.settings.type->name, m.sampler->type, "bench", args.spp, r);
      const studies::TimedRender t = studies::timedRender(
          file, *m.sampler->prototype, *m.integrator, film, args.spp, args.threads, seed);
      m.seconds.push_back(t.wallSeconds);
      m.relMse.push_back(studies::compareToReference(film, reference).relMse);
      const studies::FireflyShare f = studies::fireflyShare(film, reference);
      m.fireflies.pixels += f.pixels;
      m.fireflies.relMseSum += f.relMseSum;
      m.fireflies.allRelMseSum += f.allRelMseSum;
    }
  std::vector<double> relMse, efficiency;
  for (const Measured& m : measured) {
    relMse.push_back(std::accumulate(m.relMse.begin(), m.relMse.end(), 0.0) /
                     double(m.relMse.size()));
    efficiency.push_back(1 / (relMse.back() * median(m.seconds)));
  }
  const double best = *std::max_element(efficiency.begin(), efficiency.end());
  size_t width = 18;
  for (const Measured& m : measured) width = std::max(width, m.label.size());
  for (size_t i = 0; i < measured.size(); ++i)
    fmt::print("{:<{}} {:8.3f} s  relMSE {:.4g}  efficiency {:10.4g}  ({:.2f}x the best)\n",
               measured[i].label, width, median(measured[i].seconds), relMse[i], efficiency[i],
               efficiency[i] / best);
  for (const Measured& m : measured)
    fmt::print("{:<{}} fireflies: {:.1f} pixels per render, {:.1f}% of relMSE\n", m.label, width,
               double(m.fireflies.pixels) / args.repeats, 100 * m.fireflies.share());
  fmt::print("seconds: medians of {} alternating repeats; relMSE: their mean (epsilon {})\n",
             args.repeats, studies::kRelEpsilon);
  fmt::print(
      "fireflies: pixels whose largest sample m, over n samples, exceeds the reference r by "
      "(m - r) / n > sqrt(r^2 + epsilon) in some channel (that sample alone gives a relative "
      "squared error of at least 1), and their share of the summed relative squared error\n");
  if (referenceRelMse > 0.1 * *std::min_element(relMse.begin(), relMse.end()))
    fmt::print(
        "warning: the reference's own error is over a tenth of the runs' error; "
        "efficiencies are biased low\n");
  return 0;
}

int run(const BenchArgs& args) {
  // The camera's own resolution changes (aspect kept), so the image is the whole picture
  // and splats land where they belong.
  SceneFile file = loadScene(args.scene, SceneOverrides::atWidth(args.resolution));
  if (!args.reference.empty() && args.bdpt)
    throw VerityError("", "--reference", "--reference and --bdpt are separate measurements");
  if (!args.rrDepths.empty() && args.reference.empty())
    throw VerityError("", "--rr-depth", "compares efficiencies, so it needs --reference");
  if (!args.rrThresholds.empty() && args.reference.empty())
    throw VerityError("", "--rr-threshold", "compares efficiencies, so it needs --reference");
  if (!args.samplers.empty() && args.reference.empty())
    throw VerityError("", "--sampler", "compares efficiencies, so it needs --reference");
  if (!args.reference.empty()) return runEfficiency(file, args);
  if (args.bdpt) return runBdpt(file, args);
  IntegratorSettings settings = studies::studyIntegrator(file, "path_tracer_nee", args.maxBounces);
  const auto integrator = makeIntegrator(settings);
  const Vector2i resolution = file.scene->camera().resolution();

  fmt::print("scene {}: {} primitives, {}×{}, {} spp, path_tracer_nee, max_bounces {}\n", file.name,
             file.scene->summary().primitives, resolution.x(), resolution.y(), args.spp,
             settings.maxBounces);
  // Alternate the measurements and keep medians: the machine is shared and noisy.
  std::vector<double> raw, one, two;
  for (int r = 0; r < args.repeats; ++r) {
    raw.push_back(
        tbb::task_arena(1).execute([&] { return rawRaysPerSecond(*file.scene, 2000000); }));
    const RenderStats s1 = timedRender(file, *integrator, args.spp, 1, resolution);
    one.push_back(s1.rays / s1.seconds);
    const RenderStats s2 = timedRender(file, *integrator, args.spp, 2, resolution);
    two.push_back(s2.rays / s2.seconds);
  }
  const double rawM = median(raw), oneM = median(one), twoM = median(two);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  fmt::print("raw Embree incoherent rays, 1 thread: {:8.2f} Mrays/s\n", rawM / 1e6);
  fmt::print(
      "path tracer rays, 1 thread:           {:8.2f} Mrays/s  ({:.0f}% of raw; target >= 60%)\n",
      oneM / 1e6, 100 * oneM / rawM);
  fmt::print(
      "path tracer rays, 2 threads:          {:8.2f} Mrays/s  (speedup {:.2f}x; target >= 1.9x)\n",
      twoM / 1e6, twoM / oneM);
  fmt::print("peak memory (max RSS):                {:8.1f} MB  (target < 150 MB at 512x512)\n",
             usage.ru_maxrss / 1024.0);
  fmt::print("medians of {} alternating repeats\n", args.repeats);
  return 0;
}

}  // namespace

void addBenchCommand(CLI::App& app, const ProcessGroup& group) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = addSubcommand(
      app, "bench",
      "Raw Embree ray throughput vs the path tracer's rays/s, 2-thread speedup, memory; prints "
      "its results and writes no file",
      MpiUse::OneProcess, group);
  cmd->add_option("scene", args->scene, "Scene file (.json)")->required();
  cmd->add_option("--spp", args->spp, "Samples per pixel of each timed render")
      ->check(wholeNumber(1));
  cmd->add_option("--resolution", args->resolution,
                  "Image width in pixels, the scene's aspect ratio kept")
      ->default_str("the scene's")
      ->check(wholeNumber(1));
  addMaxBouncesOption(cmd, args->maxBounces);
  cmd->add_flag("--bdpt", args->bdpt,
                "Time bdpt against path_tracer_nee per sample, and bdpt's 2-thread speedup");
  cmd->add_option("--repeats", args->repeats, "Alternating repeats (medians are reported)")
      ->check(wholeNumber(1));
  cmd->add_option("--reference", args->reference,
                  "Reference image (.exr): print each integrator's efficiency 1 / (relMSE · s)");
  cmd->add_option("--integrator", args->integrators,
                  "Integrators compared with --reference, comma-separated")
      ->delimiter(',');
  addThreadsOption(cmd, args->threads, MpiUse::OneProcess, "of the --reference renders");
  cmd->add_option("--rr-depth", args->rrDepths,
                  "Russian roulette depths compared with --reference, comma-separated: the "
                  "scattering event after which roulette first decides (the integrator's "
                  "\"rr_depth\")")
      ->default_str("the scene's")
      ->delimiter(',')
      ->check(wholeNumber(integrator_keys::kRrDepth.allowed));
  cmd->add_option("--rr-threshold", args->rrThresholds,
                  "Russian roulette thresholds compared with --reference, comma-separated, each "
                  "with every --rr-depth: the throughput below which roulette may end a path "
                  "(the integrator's \"rr_threshold\")")
      ->default_str("the scene's")
      ->delimiter(',')
      ->check(realNumber(integrator_keys::kRrThreshold.allowed));
  cmd->add_option("--sampler", args->samplers,
                  "Samplers compared with --reference, comma-separated, each with every "
                  "integrator, alternating, with seeds of their own (a sampler other than the "
                  "scene's takes its keys' defaults); one of " +
                      samplerTypeList())
      ->default_str("the scene's")
      ->delimiter(',');
  cmd->callback([args] { throw CLI::RuntimeError(run(*args)); });
}

}  // namespace verity
