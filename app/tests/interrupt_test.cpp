// Ctrl-C during `verity render` writes the image rendered so far, correctly normalised:
// with the independent sampler, a sample's random numbers depend only on (seed, pixel,
// sample index), so a render stopped after P passes must equal, bit for bit, a render of
// P samples per pixel.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include "film/image_io.h"
#include "testing/child_process.h"

namespace verity::interrupt_test {
namespace {

using testing::spawn;
using testing::waitExit;

const char* kScene = R"({
  "camera": {"transform": {"from": [0, 0, 4], "at": [0, 0, 0], "up": [0, 1, 0]}, "vfov": 40,
             "resolution": [64, 48]},
  "integrator": {"type": "path_tracer_mis", "max_bounces": 8},
  "image_samples": 1000000,
  "background": 1,
  "surfaces": [{"type": "sphere", "radius": 1, "material": {"type": "lambertian", "albedo": 0.5}}]
})";

TEST(Interrupt, PartialImageEqualsRenderOfCompletedPasses) {
  const auto dir = std::filesystem::temp_directory_path() / "verity_interrupt_test";
  std::filesystem::create_directories(dir);
  const auto scene = dir / "scene.json";
  std::ofstream(scene) << kScene;
  const std::string partial = (dir / "partial.exr").string();
  std::filesystem::remove(partial);

  const pid_t pid = spawn({VERITY_BINARY, "render", scene.string(), "--variance", "--seed", "5",
                           "--threads", "2", "-o", partial});
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  kill(pid, SIGINT);
  EXPECT_EQ(waitExit(pid), 130) << "an interrupted render exits with 128 + SIGINT";

  const ImageChannels image = readExr(partial);
  ASSERT_TRUE(image.attributes.count("verity:partial")) << "the EXR must say it is partial";
  const int passes = std::stoi(image.attributes.at("verity:spp"));
  ASSERT_GT(passes, 0);
  ASSERT_LT(passes, 1000000);
  for (float n : image.planes.at("samples")) ASSERT_EQ(n, static_cast<float>(passes));

  const std::string complete = (dir / "complete.exr").string();
  const pid_t again = spawn({VERITY_BINARY, "render", scene.string(), "--variance", "--seed", "5",
                             "--spp", std::to_string(passes), "-o", complete});
  ASSERT_EQ(waitExit(again), 0);
  const ImageChannels reference = readExr(complete);
  for (const char* channel : {"R", "G", "B", "variance.R"}) {
    const auto& a = image.planes.at(channel);
    const auto& b = reference.planes.at(channel);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(float))) << channel;
  }
}

}  // namespace
}  // namespace verity::interrupt_test
