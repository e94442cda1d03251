// Every unbiased integrator against every other, on every shipped, stress and cross-check
// scene: path_tracer_mats, path_tracer_nee, path_tracer_mis and bdpt pairwise,
// and the light tracer against each of them. No integrator is the reference: a bug two of them
// share (the shadow rays of next-event estimation, say) still shows against the ones that do not
// share it, path_tracer_mats above all, which traces no shadow ray. Every scene at 32 pixels wide,
// max_bounces 5. Each integrator renders a scene with the sampler that its place takes in turn
// (suite_samplers.h: independent, halton, sobol along the scenes and the integrators).
//
//   - Images. Per 16×16 tile and channel, a Welch t-test of one integrator's mean against the
//     other's. The light tracer does not see delta surfaces (light_tracer.h), so its
//     comparisons pool only the pixels that see none, here or in a neighbour. One Holm
//     correction (holm.h) over every test of every tile, scene and pair: family-wise level 1%.
//   - Path lengths (cornell-box). For each k = 0 … 5, BDPT's weighted strategies of length k
//     summed against the path tracer's length-k image, per tile and channel; its own Holm
//     family at 1%.
//   - Power. The image family must reject BDPT's images made 2% brighter.
// One exclusion, measured: the light tracer on phong (lightTracerTooRare).
// Tiles are estimated by batch means (batch_regions.h): splats correlate the pixels of a
// pass, so per-pixel variances would understate a tile's. Seeds are fixed by the formula in
// seedOf, written once and never tuned.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>

#include "integrators/integrator_registry.h"
#include "integrators/integrator_settings.h"
#include "render/component_images.h"
#include "render/renderer.h"
#include "validation/compare/batch_regions.h"
#include "validation/compare/comparison_family.h"
#include "validation/compare/suite_samplers.h"
#include "validation/studies/study_scene.h"

namespace verity::validation {
namespace {

constexpr int kWidth = 32;
constexpr int kTileSize = 16;
constexpr int kMaxBounces = 5;
constexpr int kBatches = 20;
constexpr double kFamilyWiseLevel = 0.01;

const char* const kIntegrators[] = {"path_tracer_mats", "path_tracer_nee", "path_tracer_mis",
                                    "bdpt", "light_tracer"};
enum { kMaterials = 0, kNee = 1, kMis = 2, kBdpt = 3, kLightTracer = 4, kCount = 5 };

// A newly registered estimator must join the comparisons: the list above is every one.
TEST(ShippedScenes, ComparesEveryRegisteredEstimator) {
  const std::vector<std::string> listed(std::begin(kIntegrators), std::end(kIntegrators));
  EXPECT_EQ(listed, radianceIntegrators());
  EXPECT_TRUE(findIntegratorType(kIntegrators[kLightTracer])->splatsOnly);
}
// Samples per pixel of a batch. The path tracers find caustics (light through the glass or
// off the mirror onto a diffuse surface) only when a sampled direction happens to hit the
// emitter: rare, large values. A t-test needs each batch mean to be nearly normal, which
// takes many such hits per batch; at 16 spp and 8×8 tiles the cornell-box-glass tiles lit
// by the mirror's caustic rejected at p ≈ 1e-5 and agreed at 256 spp. The path tracers are
// the cheapest, so they get four times the samples.
constexpr int kBatchSpp[] = {64, 64, 64, 16, 16};

constexpr uint64_t kSeedBase = 1;

uint64_t seedOf(int scene, int integrator, int batch) {
  return kSeedBase + 100000 * uint64_t(scene) + 1000 * uint64_t(integrator) + uint64_t(batch);
}

// Whether each pixel sees, through a 5×5 grid of camera rays, only emitters, surfaces with a
// non-delta lobe and the background (no delta surface), in itself and its 8 neighbours.
std::vector<bool> lightTracerPixels(const SceneFile& file) {
  const Camera& camera = file.scene->camera();
  const int w = camera.resolution().x(), h = camera.resolution().y();
  std::vector<bool> plain(size_t(w) * h, true);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int j = 0; j < 25; ++j) {
        SurfaceInteraction si;
        const Point2f film(x + (j % 5) / 4.0f, y + (j / 5) / 4.0f);
        const bool hit = file.scene->intersect(camera.generateRay(film, Point2f(0.5f, 0.5f)), si);
        if (hit && !(si.light || (si.material && si.material->hasNonDeltaLobe())))
          plain[size_t(y) * w + x] = false;
      }
  std::vector<bool> usable(plain.size(), true);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = std::clamp(x + dx, 0, w - 1), yy = std::clamp(y + dy, 0, h - 1);
          if (!plain[size_t(yy) * w + xx]) usable[size_t(y) * w + x] = false;
        }
  return usable;
}

struct SceneStatistics {
  std::string name;
  int tiles = 0;
  std::array<std::optional<BatchRegions>, kCount> image;     // per integrator, all pixels
  std::array<std::optional<BatchRegions>, kCount> masked;    // the light tracer's pixels
  std::vector<BatchRegions> pathTracerLengths, bdptLengths;  // per k (cornell-box)
  uint64_t invalidSamples = 0;
};

SceneStatistics renderScene(int sceneIndex, const std::filesystem::path& path, bool pathLengths) {
  SceneStatistics out;
  out.name = studies::shippedSceneName(path);
  SceneFile file = loadScene(path, SceneOverrides::atWidth(kWidth));
  const Vector2i res = file.scene->camera().resolution();
  const std::vector<int> tiles = tileRegions(res.x(), res.y(), kTileSize, &out.tiles);
  std::vector<int> masked = tiles;
  const std::vector<bool> usable = lightTracerPixels(file);
  for (size_t i = 0; i < masked.size(); ++i)
    if (!usable[i]) masked[i] = -1;
  for (int k = 0; pathLengths && k <= kMaxBounces; ++k) {
    out.pathTracerLengths.emplace_back(tiles, out.tiles, fmt::format("path tracer k{}", k));
    out.bdptLengths.emplace_back(tiles, out.tiles, fmt::format("bdpt k{}", k));
  }

  for (int i = 0; i < kCount; ++i) {
    useSampler(file, suiteSampler(sceneIndex, i), kBatchSpp[i]);
    out.image[i].emplace(tiles, out.tiles, out.name + " " + kIntegrators[i]);
    out.masked[i].emplace(masked, out.tiles, out.name + " " + kIntegrators[i] + ", masked");
    IntegratorSettings settings = studies::studyIntegrator(file, kIntegrators[i], kMaxBounces);
    const auto integrator = makeIntegrator(settings);
    const bool lengths = pathLengths && (i == kNee || i == kBdpt);
    for (int batch = 0; batch < kBatches; ++batch) {
      Film film(res);
      std::optional<ComponentImages> components;
      if (lengths)
        components.emplace(ComponentLayout(ComponentLayout::Kind::PathLengths, kMaxBounces), res);
      RenderOptions options;
      options.samplesPerPixel = kBatchSpp[i];
      options.components = components ? &*components : nullptr;
      file.sampler->setSeed(seedOf(sceneIndex, i, batch));
      out.invalidSamples +=
          render(*file.scene, *integrator, *file.sampler, film, options).invalidSamples;
      out.image[i]->addBatch(film);
      out.masked[i]->addBatch(film);
      for (int k = 0; lengths && k <= kMaxBounces; ++k) {
        const int c = components->layout().pathLengthIndex(k);
        (i == kNee ? out.pathTracerLengths : out.bdptLengths)[k].addBatch(components->film(c));
      }
    }
  }
  return out;
}

// Every scene rendered by every integrator.
std::vector<SceneStatistics> renderAll() {
  const auto start = std::chrono::steady_clock::now();
  std::vector<SceneStatistics> scenes;
  const std::vector<std::filesystem::path> files = studies::shippedScenes(VERITY_SCENES_DIR);
  for (int s = 0; s < int(files.size()); ++s)
    scenes.push_back(renderScene(s, files[s], files[s].stem() == "cornell-box"));
  fmt::print("rendered {} scenes x {} integrators, {} batches of {}/{}/{}/{}/{} spp, in {:.1f} s\n",
             scenes.size(), int(kCount), kBatches, kBatchSpp[0], kBatchSpp[1], kBatchSpp[2],
             kBatchSpp[3], kBatchSpp[4],
             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return scenes;
}

// Whether the light tracer's pixels of a scene hold anything to compare.
bool anyMaskedPixel(const SceneStatistics& s) {
  const PixelStatistics m = s.masked[kNee]->statistics();
  return std::any_of(m.samples.begin(), m.samples.end(), [](double n) { return n > 0; });
}

// Scenes where the light tracer's estimate of the masked pixels rests on events too rare for
// this test's 320 spp: on phong, the background's reflection in the exponent-798 sphere needs a
// light path leaving the environment's disk within the lobe's few hundredths of a radian. Its
// batch means are then nowhere near normal: mostly low, with low spread. Measured on phong at
// 32×13, light_tracer against path_tracer_mis (20,000 spp): 20,000 light-tracer spp read the
// blue of pixel (7, 5) as 0.0451 against 0.0606 (t = 17); 200,000 read 0.0701 (t = −0.7), and
// every rejected pixel likewise agreed. An unbiased but heavy-tailed estimate, so left out
// rather than compared with a t-test whose assumption fails; the other integrators still meet
// every other pair on this scene.
bool lightTracerTooRare(const std::string& scene) {
  return scene == "phong";
}

// The family of every pair's image comparisons, with BDPT's images scaled by `bdptGain`.
ComparisonFamily imageFamily(const std::vector<SceneStatistics>& scenes, double bdptGain) {
  ComparisonFamily family(kFamilyWiseLevel);
  const auto statistics = [&](const std::optional<BatchRegions>& regions, int i) {
    return i == kBdpt ? scaledStatistics(regions->statistics(), bdptGain) : regions->statistics();
  };
  for (const SceneStatistics& s : scenes)
    for (int a = 0; a < kCount; ++a)
      for (int b = a + 1; b < kCount; ++b) {
        const std::string name =
            fmt::format("{}: {} / {}", s.name, kIntegrators[a], kIntegrators[b]);
        if (b != kLightTracer)
          family.add(name, statistics(s.image[a], a), statistics(s.image[b], b));
        else if (anyMaskedPixel(s) && !lightTracerTooRare(s.name))
          family.add(name + ", masked", statistics(s.masked[a], a), s.masked[b]->statistics());
      }
  return family;
}

// One test, so that CTest (which runs each test in its own process) renders once.
TEST(ShippedScenes, EveryIntegratorMatchesEveryOther) {
  const std::vector<SceneStatistics> scenes = renderAll();
  for (const SceneStatistics& s : scenes) EXPECT_EQ(s.invalidSamples, 0u) << s.name;
  EXPECT_EQ(imageFamily(scenes, 1).decide("images, all scenes").rejections, 0);

  // Per path length k on cornell-box: BDPT's weighted strategies of length k summed.
  const SceneStatistics& box = *std::find_if(scenes.begin(), scenes.end(),
                                             [](const auto& s) { return s.name == "cornell-box"; });
  ASSERT_EQ(box.bdptLengths.size(), size_t(kMaxBounces + 1));
  ComparisonFamily lengths(kFamilyWiseLevel);
  for (int k = 0; k <= kMaxBounces; ++k)
    lengths.add(fmt::format("{}: length {}", box.name, k), box.pathTracerLengths[k].statistics(),
                box.bdptLengths[k].statistics());
  EXPECT_EQ(lengths.decide("path lengths, cornell-box").rejections, 0);

  // Power: the image family must fail when BDPT is 2% too bright everywhere. The power bound
  // must cover 2% before the detection means anything; a 1% error in one scene is shown
  // detected by end_to_end_test and bdpt_strategies_test at their sample counts.
  const ComparisonFamily::Decision brighter = imageFamily(scenes, 1.02).decide("bdpt 2% brighter");
  ASSERT_LT(brighter.detectableBias, 0.02);
  EXPECT_GT(brighter.rejections, 0);
}

}  // namespace
}  // namespace verity::validation
