#include "app/bench_command.h"

#include <fmt/format.h>
#include <sys/resource.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>

#include "render/renderer.h"
#include "sampling/independent_sampler.h"
#include "sampling/warp.h"
#include "scene/scene_loader.h"

namespace verity {

namespace {

struct BenchArgs {
  std::string scene;
  int spp = 8;
  int resolution = 0;
  int repeats = 3;
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

int run(const BenchArgs& args) {
  SceneFile file = loadScene(args.scene);
  IntegratorSettings settings = file.integrator;
  settings.type = "path_tracer_nee";
  const auto integrator = makeIntegrator(settings);
  Vector2i resolution = file.scene->camera().resolution();
  if (args.resolution > 0) resolution = Vector2i(args.resolution, args.resolution);

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
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
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

void addBenchCommand(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Raw Embree ray throughput vs the path tracer's rays/s, 2-thread speedup, memory");
  cmd->add_option("scene", args->scene, "Scene file (.json)")->required();
  cmd->add_option("--spp", args->spp, "Samples per pixel of each timed render")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--resolution", args->resolution, "Square resolution (default: the scene's)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--repeats", args->repeats, "Alternating repeats (medians are reported)")
      ->check(CLI::PositiveNumber);
  cmd->callback([args] { throw CLI::RuntimeError(run(*args)); });
}

}  // namespace verity
