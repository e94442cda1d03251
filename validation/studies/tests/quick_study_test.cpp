// A quick end-to-end study on a 16×16 Cornell box: reference, convergence study (written as
// JSON Lines, interrupted and resumed), summary and report. For the unbiased path tracers the
// fitted log-log slope of relative MSE against spp must be consistent with −1.
//
// Why −1 (e.g. Veach 1997, section 2.4; Owen, "Monte Carlo theory, methods and examples",
// chapter 2): a pixel mean of n independent samples has variance σ²/n, so with reference r
// E[(x̄ − r)²] = σ²/n + (μ − r)², and the relative MSE is A/n + B with B the reference's own
// error, of the order of its estimated relative MSE. With a reference of 4096 spp against
// budgets of at most 32 spp, B/(A/32) ≈ 32/4096 < 1%, which moves the slope by less than
// log(1.008)/log(16) ≈ 0.003, far inside the interval below.
// The runs are seeded by (integrator, sampler, budget, run) and renders are bit-identical for any
// thread count, so the test's outcome is deterministic; its statistical content is that the
// 95% interval of an unbiased estimator covers −1 with probability 0.95.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "film/image_io.h"
#include "testing/error_of.h"
#include "validation/studies/convergence.h"
#include "validation/studies/json_lines.h"
#include "validation/studies/reference.h"
#include "validation/studies/report.h"
#include "validation/studies/speedup.h"
#include "validation/studies/strategies.h"
#include "validation/studies/summary.h"

namespace verity::studies {
namespace {

namespace fs = std::filesystem;

size_t countLines(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  size_t n = 0;
  while (std::getline(in, line)) n += !line.empty();
  return n;
}

TEST(QuickStudy, CornellBoxEndToEnd) {
  const fs::path dir =
      fs::path(testing::TempDir()) / ("verity-quick-study-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = fs::path(VERITY_SOURCE_DIR) / "scenes" / "cornell-box.json";

  // Reference.
  ReferenceConfig ref;
  ref.scene = scene;
  ref.spp = 4096;
  ref.integrator = "path_tracer_mis";
  ref.resolution = 16;
  ref.directory = dir / "references";
  const ReferenceResult reference = makeReference(ref);
  ASSERT_TRUE(fs::exists(reference.image));
  ASSERT_TRUE(fs::exists(reference.sidecar));
  const ImageChannels image = readExr(reference.image);
  EXPECT_EQ(image.width, 16);
  EXPECT_EQ(image.height, 16);
  for (const char* c : {"R", "G", "B", "variance.R", "variance.G", "variance.B", "samples"})
    EXPECT_TRUE(image.planes.count(c)) << c;
  for (const char* key :
       {"integrator", "spp", "seed", "wall_seconds", "threads", "machine", "revision", "rel_mse"})
    EXPECT_TRUE(reference.metadata.contains(key)) << key;
  EXPECT_EQ(reference.metadata["spp"], 4096);
  EXPECT_GT(reference.metadata["rel_mse"].get<double>(), 0);
  EXPECT_LT(reference.metadata["rel_mse"].get<double>(), 1e-2);

  // Convergence study, then an interruption simulated by cutting the file after 7 records
  // and half of the 8th: the rerun must redo exactly the missing runs.
  ConvergenceConfig study;
  study.scene = scene;
  study.integrators = {"path_tracer_nee", "path_tracer_mis"};
  study.runs = 6;
  study.budgets = {2, 4, 8, 16, 32};
  study.threads = {0};
  study.reference = reference.image;
  study.output = dir / "results.jsonl";
  const int total = 6 * 5 * 2;
  StudyProgress first = runConvergenceStudy(study, nullptr);
  EXPECT_EQ(first.done, total);
  EXPECT_EQ(countLines(study.output), size_t(total));
  {
    std::ifstream in(study.output);
    std::string all, line;
    for (int i = 0; i < 7 && std::getline(in, line); ++i) all += line + "\n";
    std::getline(in, line);
    all += line.substr(0, line.size() / 2);  // torn write
    in.close();
    std::ofstream(study.output, std::ios::trunc) << all;
  }
  const StudyProgress resumed = runConvergenceStudy(study, nullptr);
  EXPECT_EQ(resumed.skipped, 7);
  EXPECT_EQ(resumed.done, total - 7);
  const std::vector<nlohmann::json> records = readJsonLines(study.output);
  ASSERT_EQ(records.size(), size_t(total));
  for (const nlohmann::json& r : records)
    for (const char* key : {"seed", "wall_seconds", "cpu_seconds", "rel_mse", "mean_variance",
                            "spp", "threads", "integrator", "budget", "run"})
      EXPECT_TRUE(r.contains(key)) << key;

  // Slopes against spp.
  const Summary summary = summarize(records, "quick.jsonl");
  int checked = 0;
  for (const ConvergenceGroup& g : summary.convergence) {
    const LineFit& f = g.fitSpp;
    SCOPED_TRACE(g.key.integrator);
    EXPECT_EQ(f.n, 30);
    EXPECT_LE(f.slopeLow, -1.0) << summaryText(summary);
    EXPECT_GE(f.slopeHigh, -1.0) << summaryText(summary);
    ++checked;
  }
  EXPECT_EQ(checked, 2);

  // Report.
  const fs::path report = dir / "report";
  ASSERT_EQ(makeReport({study.output}, report), 0);
  for (const char* f : {"index.html", "summary.md", "summary.json", "error_vs_time.png",
                        "efficiency.png", "relative_error_images.png"})
    EXPECT_TRUE(fs::exists(report / f)) << f;
  fs::remove_all(dir);
}

// The strategies study: the MIS-weighted strategy images add up to the image, so the shares
// add up to 1 (to float rounding); a second run with the same arguments is skipped, and the
// summary names fewer strategies than there are that carry at least kCarriedShare.
TEST(QuickStudy, StrategiesSharesAddUpAndResume) {
  const fs::path dir =
      fs::path(testing::TempDir()) / ("verity-strategies-study-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  StrategiesConfig config;
  config.scene = fs::path(VERITY_SOURCE_DIR) / "scenes" / "cornell-box.json";
  config.budgets = {8};
  config.resolution = 16;
  config.maxBounces = 3;
  config.output = dir / "strategies.jsonl";
  EXPECT_EQ(runStrategiesStudy(config, nullptr).done, 1);
  EXPECT_EQ(runStrategiesStudy(config, nullptr).skipped, 1);
  const std::vector<nlohmann::json> records = readJsonLines(config.output);
  ASSERT_EQ(records.size(), 1u);
  double total = 0;
  for (const nlohmann::json& st : records[0]["strategies"]) total += st["share"].get<double>();
  EXPECT_NEAR(total, 1.0, 1e-4);
  EXPECT_EQ(records[0]["strategies"].size(), 14u);  // (s, t) with s + t − 2 ≤ 3, t ≥ 1

  const Summary summary = summarize(records, "quick.jsonl");
  ASSERT_EQ(summary.strategies.size(), 1u);
  const StrategiesSummary& g = summary.strategies[0];
  EXPECT_GE(g.carriedShare, kCarriedShare);
  EXPECT_LT(g.carrying.size(), g.ranked.size());
  fs::remove_all(dir);
}

// A speedup record read back to resume a study names what it lacks, rather than reading as
// repeat 0 and hiding a run.
TEST(QuickStudy, AResumedSpeedupRecordWithoutAKeyIsAnError) {
  const fs::path dir =
      fs::path(testing::TempDir()) / ("verity-speedup-resume-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  SpeedupConfig config;
  config.scene = fs::path(VERITY_SOURCE_DIR) / "scenes" / "cornell-box.json";
  config.integrators = {"path_tracer_nee"};
  config.threads = {1};
  config.spp = 1;
  config.repeats = 2;
  config.resolution = 8;
  config.output = dir / "speedup.jsonl";
  EXPECT_EQ(runSpeedupStudy(config, nullptr).done, 2);
  std::vector<nlohmann::json> records = readJsonLines(config.output);
  records[1].erase("repeat");
  {
    std::ofstream out(config.output, std::ios::trunc);
    for (const nlohmann::json& r : records) out << r.dump() << "\n";
  }
  EXPECT_EQ(errorOf([&] { runSpeedupStudy(config, nullptr); }),
            config.output.string() + ": record 2, \"repeat\": missing key");
  fs::remove_all(dir);
}

// A strategies record read back to resume a study names what it lacks, rather than reading as
// a record of budget = its spp, run 0 and no path tracer, which would skip a run not done.
TEST(QuickStudy, AResumedStrategiesRecordWithoutAKeyIsAnError) {
  const fs::path dir =
      fs::path(testing::TempDir()) / ("verity-strategies-resume-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  StrategiesConfig config;
  config.scene = fs::path(VERITY_SOURCE_DIR) / "scenes" / "cornell-box.json";
  config.budgets = {2};
  config.resolution = 8;
  config.maxBounces = 1;
  config.images = false;
  config.output = dir / "strategies.jsonl";
  EXPECT_EQ(runStrategiesStudy(config, nullptr).done, 1);
  const nlohmann::json written = readJsonLines(config.output).at(0);
  auto resumedWith = [&](const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json record = written;
    change(record);
    std::ofstream(config.output, std::ios::trunc) << record.dump() << "\n";
    return errorOf([&] { runStrategiesStudy(config, nullptr); });
  };
  const std::string where = config.output.string() + ": record 1, ";
  for (const char* key : {"scene", "width", "budget_type", "budget", "run", "path_tracer"})
    EXPECT_EQ(resumedWith([&](nlohmann::json& r) { r.erase(key); }),
              where + "\"" + key + "\": missing key");
  EXPECT_EQ(resumedWith([](nlohmann::json& r) { r["path_tracer"].erase("integrator"); }),
            where + "\"path_tracer\", \"integrator\": missing key");
  EXPECT_EQ(resumedWith([](nlohmann::json& r) { r["budget_type"] = "seconds"; }),
            where + "\"budget_type\": expected \"spp\" or \"time\", found \"seconds\"");
  // The record as written resumes: its run is skipped.
  std::ofstream(config.output, std::ios::trunc) << written.dump() << "\n";
  EXPECT_EQ(runStrategiesStudy(config, nullptr).skipped, 1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace verity::studies
