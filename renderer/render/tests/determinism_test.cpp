// The image must be bit-identical for any thread count.
#include <gtest/gtest.h>

#include <cstring>

#include "film/image_io.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

namespace verity {
namespace {

const char* kScene = R"({
  "camera": {"transform": {"from": [0, 1, 6], "at": [0, 0, 0], "up": [0, 1, 0]}, "vfov": 50,
             "resolution": [40, 36]},
  "integrator": {"type": "path_tracer_mis", "max_bounces": 6},
  "sampler": {"type": "stratified", "samples": 4},
  "background": [0.2, 0.3, 0.4],
  "surfaces": [
    {"type": "sphere", "radius": 1, "material": {"type": "lambertian", "albedo": [0.8, 0.5, 0.3]}},
    {"type": "quad", "size": 10, "transform": [{"axis": [1, 0, 0], "angle": -90}, {"translate": [0, -1, 0]}],
     "material": {"type": "lambertian", "albedo": {"type": "checker", "even": 0.8, "odd": 0.2}}},
    {"type": "quad", "size": 1, "transform": [{"axis": [1, 0, 0], "angle": 90}, {"translate": [0, 3, 0]}],
     "material": {"type": "diffuse light", "emit": 10}}
  ]
})";

std::vector<float> renderWithThreads(int threads) {
  SceneFile file = loadSceneText(kScene, "/tmp/determinism.json");
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

TEST(Determinism, ByteIdenticalForOneTwoAndThreeThreads) {
  const auto one = renderWithThreads(1);
  ASSERT_FALSE(one.empty());
  double total = 0;
  for (float v : one) total += v;
  EXPECT_GT(total, 0) << "the test scene must not be black";
  for (int threads : {2, 3}) {
    const auto other = renderWithThreads(threads);
    ASSERT_EQ(one.size(), other.size());
    EXPECT_EQ(0, std::memcmp(one.data(), other.data(), one.size() * sizeof(float)))
        << threads << " threads differ from one";
  }
}

}  // namespace
}  // namespace verity
