// `mpirun -n 2 verity study convergence` against one process: the same runs (keys, seeds and,
// for budgets of samples, relative MSE to the bit), rank 0 alone writing, both ranks working,
// a resumed job skipping everything; and timed runs that would share cores are refused.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <thread>

#include "distributed/tests/mpi_launcher.h"
#include "validation/studies/json_lines.h"

namespace verity::studies {
namespace {

namespace fs = std::filesystem;
using mpi_testing::run;
using mpi_testing::underMpirun;

std::string key(const nlohmann::json& r) {
  return fmt::format("{}|{}|{}|{}|{}", r.at("integrator").get<std::string>(),
                     r.at("threads").get<int>(), r.at("budget").get<double>(),
                     r.at("run").get<int>(), r.at("width").get<int>());
}

TEST(RunDistribution, TwoRanksRecordWhatOneProcessRecords) {
  const fs::path dir = fs::temp_directory_path() / "verity_run_distribution_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene = (fs::path(VERITY_SOURCE_DIR) / "scenes/cornell-box.json").string();
  const auto made =
      run({VERITY_BINARY, "reference", scene, "--spp", "16", "--resolution", "16", "--integrator",
           "path_tracer_nee", "--threads", "1", "-o", (dir / "ref").string()});
  ASSERT_EQ(made.status, 0) << made.stderrText;
  const auto study = [&](const fs::path& out) {
    return std::vector<std::string>{VERITY_BINARY,
                                    "study",
                                    "convergence",
                                    scene,
                                    "--integrator",
                                    "path_tracer_nee,bdpt",
                                    "--runs",
                                    "2",
                                    "--spp",
                                    "2,4",
                                    "--threads",
                                    "1",
                                    "--max-bounces",
                                    "4",
                                    "--reference",
                                    (dir / "ref/cornell-box.exr").string(),
                                    "--no-error-images",
                                    "-o",
                                    out.string()};
  };
  const auto alone = run(study(dir / "single.jsonl"));
  ASSERT_EQ(alone.status, 0) << alone.stderrText;
  const auto job = run(underMpirun(2, study(dir / "two.jsonl")));
  ASSERT_EQ(job.status, 0) << job.stderrText;

  const auto single = readJsonLines(dir / "single.jsonl");
  const auto two = readJsonLines(dir / "two.jsonl");
  ASSERT_EQ(single.size(), 8u);
  ASSERT_EQ(two.size(), single.size());
  std::map<std::string, nlohmann::json> byKey;
  for (const auto& r : single) byKey[key(r)] = r;
  std::set<int> ranks;
  for (const auto& r : two) {
    ASSERT_TRUE(byKey.count(key(r))) << key(r);
    const nlohmann::json& expected = byKey.at(key(r));
    EXPECT_EQ(r.at("seed"), expected.at("seed")) << key(r);
    EXPECT_EQ(r.at("rel_mse").get<double>(), expected.at("rel_mse").get<double>()) << key(r);
    EXPECT_FALSE(r.at("hostname").get<std::string>().empty());
    ranks.insert(r.at("mpi_rank").get<int>());
  }
  EXPECT_EQ(ranks, (std::set<int>{0, 1})) << "both ranks run";

  const auto resumed = run(underMpirun(2, study(dir / "two.jsonl")));
  ASSERT_EQ(resumed.status, 0) << resumed.stderrText;
  EXPECT_EQ(readJsonLines(dir / "two.jsonl").size(), two.size());
  EXPECT_NE(resumed.stderrText.find("0 runs done, 8 already"), std::string::npos)
      << resumed.stderrText;
  fs::remove_all(dir);
}

TEST(RunDistribution, TimedRunsThatWouldShareCoresAreRefused) {
  const fs::path dir = fs::temp_directory_path() / "verity_run_distribution_cores_test";
  fs::create_directories(dir);
  const std::string scene = (fs::path(VERITY_SOURCE_DIR) / "scenes/cornell-box.json").string();
  const std::string cores = std::to_string(std::max(1u, std::thread::hardware_concurrency()));
  const auto job =
      run(underMpirun(2, {VERITY_BINARY, "study", "speedup", scene, "--integrator",
                          "path_tracer_nee", "--threads", cores, "--spp", "1", "--resolution", "16",
                          "--repeats", "1", "-o", (dir / "speedup.jsonl").string()}));
  EXPECT_NE(job.status, 0);
  EXPECT_NE(job.stderrText.find("timed runs sharing cores"), std::string::npos) << job.stderrText;
  EXPECT_FALSE(fs::exists(dir / "speedup.jsonl"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace verity::studies
