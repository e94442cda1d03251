// The image must be bit-identical for any thread count, with every sampler: a sampler's values
// depend on (seed, pixel, sample index, dimension) alone, not on which thread draws them.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "film/image_io.h"
#include "loader/scene_loader.h"
#include "render/renderer.h"
#include "sampling/sampler.h"

namespace verity {
namespace {

// A lit sphere on a checkered floor, rendered with the scene-format sampler object `sampler`.
std::string sceneWithSampler(const std::string& sampler) {
  return R"({
  "camera": {"transform": {"from": [0, 1, 6], "at": [0, 0, 0], "up": [0, 1, 0]}, "vfov": 50,
             "resolution": [40, 36]},
  "integrator": {"type": "path_tracer_mis", "max_bounces": 6},
  "sampler": )" +
         sampler + R"(,
  "background": [0.2, 0.3, 0.4],
  "surfaces": [
    {"type": "sphere", "radius": 1, "material": {"type": "lambertian", "albedo": [0.8, 0.5, 0.3]}},
    {"type": "quad", "size": 10, "transform": [{"axis": [1, 0, 0], "angle": -90}, {"translate": [0, -1, 0]}],
     "material": {"type": "lambertian", "albedo": {"type": "checker", "even": 0.8, "odd": 0.2}}},
    {"type": "quad", "size": 1, "transform": [{"axis": [1, 0, 0], "angle": 90}, {"translate": [0, 3, 0]}],
     "material": {"type": "diffuse light", "emit": 10}}
  ]
})";
}

// Every channel of the render, variance channels included, as one array.
std::vector<float> renderWithThreads(SceneFile& file, int threads) {
  const auto integrator = makeIntegrator(file.integrator);
  Film film(file.scene->camera().resolution());
  RenderOptions options;
  options.samplesPerPixel = file.sampler->samplesPerPixel();
  options.threads = threads;
  file.sampler->setSeed(3);
  render(*file.scene, *integrator, *file.sampler, film, options);
  std::vector<float> values;
  for (const auto& [name, plane] : filmChannels(film, true).planes)
    values.insert(values.end(), plane.begin(), plane.end());
  return values;
}

std::vector<float> renderWithThreads(const std::string& sampler, int threads) {
  SceneFile file = loadSceneText(sceneWithSampler(sampler), "/tmp/determinism.json");
  return renderWithThreads(file, threads);
}

// Renders with one thread, then with each of `threads`, and compares the bytes.
void expectSameForThreads(const std::string& sampler, std::initializer_list<int> threads) {
  const auto one = renderWithThreads(sampler, 1);
  ASSERT_FALSE(one.empty());
  double total = 0;
  for (float v : one) total += v;
  EXPECT_GT(total, 0) << sampler << ": the test scene must not be black";
  for (int n : threads) {
    const auto other = renderWithThreads(sampler, n);
    ASSERT_EQ(one.size(), other.size());
    EXPECT_EQ(0, std::memcmp(one.data(), other.data(), one.size() * sizeof(float)))
        << sampler << ": " << n << " threads differ from one";
  }
}

TEST(Determinism, ByteIdenticalForOneTwoAndThreeThreads) {
  expectSameForThreads(R"({"type": "stratified", "samples": 4})", {2, 3});
}

TEST(SamplerDeterminism, EachSamplerByteIdenticalForOneAndTwoThreads) {
  for (const char* sampler :
       {R"({"type": "independent", "samples": 5})", R"({"type": "halton", "samples": 5})",
        R"({"type": "halton", "randomization": "permute_digits", "samples": 5})",
        R"({"type": "sobol", "samples": 5})", R"({"type": "stratified", "samples": 7})"})
    expectSameForThreads(sampler, {2});
}

// Every shipped scene (scenes/*.json) with each correlated sampler: each scene's integrator,
// materials and lights ask for dimensions in their own order. Thread dependence shows only
// where the second thread takes tiles, so the renders are large enough for it to: 64 pixels
// wide at 16 spp, several tiles (a render of one tile, as above, cannot show it).
constexpr int kSceneWidth = 64, kSceneSpp = 16;

TEST(SamplerDeterminism, EveryShippedSceneWithEachSamplerForOneAndTwoThreads) {
  int scenes = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(VERITY_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    ++scenes;
    for (const char* type : {"stratified", "halton", "sobol"}) {
      SCOPED_TRACE(entry.path().filename().string() + ", " + type);
      SceneFile file = loadScene(entry.path(), SceneOverrides::atWidth(kSceneWidth));
      file.sampler = makeSampler(type, "sampler");
      file.sampler->setSamplesPerPixel(kSceneSpp);
      const auto one = renderWithThreads(file, 1), two = renderWithThreads(file, 2);
      ASSERT_EQ(one.size(), two.size());
      EXPECT_EQ(0, std::memcmp(one.data(), two.data(), one.size() * sizeof(float)));
    }
  }
  EXPECT_GE(scenes, 16);
}

}  // namespace
}  // namespace verity
