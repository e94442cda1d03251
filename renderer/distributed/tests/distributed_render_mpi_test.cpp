// `mpirun -n N verity render|reference` against one process without mpirun: the same image,
// bit for bit, for 1, 2 and 3 ranks and several thread counts, with a path tracer and with
// BDPT (whose t = 1 strategy splats onto other pixels); a rank that dies fails the job and
// leaves no image; Ctrl-C leaves a partial image that a render of its pass count equals.
// 18 samples per pixel make chunks of 4, 4, 4, 4 and 2 passes (render/pass_chunks.h), so
// every rank renders and rank 0 takes two chunks from itself and a short one from rank 1.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "film/image_io.h"
#include "mpi_launcher.h"

namespace verity {
namespace {

namespace fs = std::filesystem;
using mpi_testing::run;
using mpi_testing::underMpirun;

class DistributedRender : public ::testing::Test {
 protected:
  void SetUp() override {
    // One folder per test: ctest -j runs them side by side.
    dir_ = fs::temp_directory_path() /
           (std::string("verity_distributed_render_test_") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // The shipped Cornell box at 40×30: edge tiles are partial.
    nlohmann::json scene = nlohmann::json::parse(
        std::ifstream(fs::path(VERITY_SOURCE_DIR) / "scenes/cornell-box.json"));
    scene["camera"]["resolution"] = {40, 30};
    scene_ = (dir_ / "cornell-box.json").string();
    std::ofstream(scene_) << scene.dump(2);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> renderArgs(const std::string& integrator, int threads,
                                      const fs::path& out, int spp = 18) const {
    return {VERITY_BINARY,           "render",     scene_, "--integrator",  integrator, "--spp",
            std::to_string(spp),     "--seed",     "7",    "--max-bounces", "6",        "--threads",
            std::to_string(threads), "--variance", "-o",   out.string()};
  }

  fs::path dir_;
  std::string scene_;
};

// The film's own bits (sums in double precision; the image rounds them to float, which hides
// a change in the order of the additions), as the hidden hook prints them.
std::string filmDigest(const std::string& stderrText) {
  const std::string tag = "film digest ";
  const size_t at = stderrText.find(tag);
  return at == std::string::npos ? "none" : stderrText.substr(at + tag.size(), 16);
}

// Every channel's bytes and every attribute but the one that names the ranks.
void expectSameImage(const fs::path& expected, const fs::path& actual) {
  const ImageChannels a = readExr(expected), b = readExr(actual);
  ASSERT_EQ(a.planes.size(), b.planes.size());
  for (const auto& [name, plane] : a.planes) {
    const auto& other = b.planes.at(name);
    ASSERT_EQ(plane.size(), other.size());
    EXPECT_EQ(0, std::memcmp(plane.data(), other.data(), plane.size() * sizeof(float)))
        << actual << ": channel " << name << " differs";
  }
  auto attributes = b.attributes;
  attributes.erase("verity:processes");
  EXPECT_EQ(a.attributes, attributes);
}

TEST_F(DistributedRender, RanksAndThreadsGiveTheSingleProcessImage) {
  for (const std::string integrator : {"path_tracer_nee", "bdpt"}) {
    const fs::path single = dir_ / (integrator + "_single.exr");
    setenv("VERITY_TEST_FILM_DIGEST", "1", 1);
    const auto alone = run(renderArgs(integrator, 2, single));
    unsetenv("VERITY_TEST_FILM_DIGEST");
    ASSERT_EQ(alone.status, 0) << alone.stderrText;
    ASSERT_NE(filmDigest(alone.stderrText), "none") << alone.stderrText;
    for (const auto& [ranks, threads] :
         std::vector<std::pair<int, int>>{{1, 2}, {2, 1}, {3, 1}, {2, 3}}) {
      const fs::path out =
          dir_ / fmt::format("{}_{}ranks_{}threads.exr", integrator, ranks, threads);
      const auto job = run(
          underMpirun(ranks, renderArgs(integrator, threads, out), {"VERITY_TEST_FILM_DIGEST=1"}));
      ASSERT_EQ(job.status, 0) << job.stderrText;
      SCOPED_TRACE(out.string());
      EXPECT_EQ(filmDigest(job.stderrText), filmDigest(alone.stderrText));
      expectSameImage(single, out);
      const ImageChannels image = readExr(out);
      if (ranks > 1) {
        EXPECT_EQ(image.attributes.at("verity:processes")
                      .rfind(fmt::format("{} MPI ranks, {} threads", ranks, threads), 0),
                  0u)
            << image.attributes.at("verity:processes");
      }
    }
  }
}

// The correlated samplers too: each of their values is a function of (seed, pixel, sample
// index, dimension), so splitting the image over ranks changes no bit.
TEST_F(DistributedRender, EverySamplerGivesTheSingleProcessImageAcrossRanks) {
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(scene_));
  for (const std::string sampler : {"stratified", "halton", "sobol"}) {
    scene["sampler"] = {{"type", sampler}};
    const fs::path file = dir_ / (sampler + ".json");
    std::ofstream(file) << scene.dump(2);
    const auto args = [&](const fs::path& out) {
      std::vector<std::string> a = renderArgs("path_tracer_nee", 1, out);
      a[2] = file.string();
      std::erase(a, "--variance");  // refused: correlated samples give no pixel variance
      return a;
    };
    const fs::path single = dir_ / (sampler + "_single.exr"), split = dir_ / (sampler + "_3.exr");
    setenv("VERITY_TEST_FILM_DIGEST", "1", 1);
    const auto alone = run(args(single));
    unsetenv("VERITY_TEST_FILM_DIGEST");
    ASSERT_EQ(alone.status, 0) << alone.stderrText;
    const auto job = run(underMpirun(3, args(split), {"VERITY_TEST_FILM_DIGEST=1"}));
    ASSERT_EQ(job.status, 0) << job.stderrText;
    SCOPED_TRACE(sampler);
    EXPECT_EQ(filmDigest(job.stderrText), filmDigest(alone.stderrText));
    expectSameImage(single, split);
  }
}

TEST_F(DistributedRender, ReferenceAcrossRanksIsTheSingleProcessReference) {
  const auto args = [&](const fs::path& out) {
    return std::vector<std::string>{
        VERITY_BINARY, "reference",    scene_,      "--spp",         "18", "--resolution",
        "24",          "--integrator", "bdpt",      "--max-bounces", "4",  "--threads",
        "1",           "-o",           out.string()};
  };
  const auto alone = run(args(dir_ / "single"));
  ASSERT_EQ(alone.status, 0) << alone.stderrText;
  const auto job = run(underMpirun(3, args(dir_ / "three")));
  ASSERT_EQ(job.status, 0) << job.stderrText;
  expectSameImage(dir_ / "single/cornell-box.exr", dir_ / "three/cornell-box.exr");
  const nlohmann::json sidecar =
      nlohmann::json::parse(std::ifstream(dir_ / "three/cornell-box.json"));
  EXPECT_EQ(sidecar.at("ranks"), 3);
}

TEST_F(DistributedRender, ComponentImagesAreRefusedAcrossRanks) {
  auto args = renderArgs("bdpt", 1, dir_ / "image.exr");
  args.push_back("--strategies");
  args.push_back((dir_ / "strategies").string());
  const auto job = run(underMpirun(2, args));
  EXPECT_NE(job.status, 0);
  EXPECT_NE(job.stderrText.find("component images are rendered by one process"), std::string::npos)
      << job.stderrText;
}

TEST_F(DistributedRender, DeadRankFailsTheJobAndLeavesNoImage) {
  const fs::path out = dir_ / "killed.exr";
  const auto job =
      run(underMpirun(3, renderArgs("path_tracer_nee", 1, out, 400), {"VERITY_TEST_KILL_RANK=1"}));
  EXPECT_NE(job.status, 0) << job.stderrText;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out.string() + ".writing"));
}

// Ctrl-C in a terminal reaches mpirun, which sends SIGTERM to every rank: each stops after the
// pass in flight and rank 0 writes what the ranks finished, in chunk order.
TEST_F(DistributedRender, InterruptedJobWritesAConsistentPartialImage) {
  const fs::path partial = dir_ / "partial.exr";
  const std::string log = (dir_ / "mpirun.txt").string();
  const pid_t pid =
      mpi_testing::spawn(underMpirun(3, renderArgs("path_tracer_nee", 1, partial, 1000000)), log);
  std::this_thread::sleep_for(std::chrono::seconds(6));
  kill(pid, SIGINT);
  const auto job = mpi_testing::finish(pid, log);
  ASSERT_TRUE(fs::exists(partial)) << "status " << job.status << "\n" << job.stderrText;
  const ImageChannels image = readExr(partial);
  ASSERT_TRUE(image.attributes.count("verity:partial"));
  const int passes = std::stoi(image.attributes.at("verity:spp"));
  ASSERT_GT(passes, 0);
  for (float n : image.planes.at("samples")) ASSERT_EQ(n, float(passes));

  const fs::path complete = dir_ / "complete.exr";
  const auto alone = run(renderArgs("path_tracer_nee", 2, complete, passes));
  ASSERT_EQ(alone.status, 0) << alone.stderrText;
  const ImageChannels reference = readExr(complete);
  for (const char* channel : {"R", "G", "B", "variance.R", "samples"}) {
    const auto& a = image.planes.at(channel);
    const auto& b = reference.planes.at(channel);
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(float))) << channel;
  }
}

}  // namespace
}  // namespace verity
