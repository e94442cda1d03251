// Samplers compared by the convergence study: every record says which sampler made it, each
// sampler's runs have seeds of their own, only independent samples give a rel_variance, an
// unknown sampler is an error naming --sampler, and the summary fits each (integrator,
// sampler) group from its own records: checked against slopes, intervals and times to
// accuracy computed by hand from synthetic records.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "testing/error_of.h"
#include "validation/studies/convergence.h"
#include "validation/studies/json_lines.h"
#include "validation/studies/reference.h"
#include "validation/studies/summary.h"

namespace verity::studies {
namespace {

namespace fs = std::filesystem;

class SamplerStudy : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(testing::TempDir()) /
           ("verity-sampler-study-" + std::to_string(getpid()) + "-" +
            testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    ReferenceConfig ref;
    ref.scene = scene_;
    ref.spp = 64;
    ref.integrator = "path_tracer_nee";
    ref.resolution = 8;
    ref.directory = dir_;
    study_.scene = scene_;
    study_.integrators = {"path_tracer_nee"};
    study_.runs = 2;
    study_.budgets = {1, 2};
    study_.threads = {1};
    study_.reference = makeReference(ref).image;
    study_.output = dir_ / "results.jsonl";
    study_.errorImages = false;
  }
  void TearDown() override { fs::remove_all(dir_); }

  const fs::path scene_ = fs::path(VERITY_SOURCE_DIR) / "scenes" / "cornell-box.json";
  fs::path dir_;
  ConvergenceConfig study_;
};

TEST_F(SamplerStudy, RecordsCarryTheSamplerAndEachSamplerIsASummaryRow) {
  study_.samplers = {"independent", "Sobol"};  // any case the registry's names take
  EXPECT_EQ(runConvergenceStudy(study_, nullptr).done, 8);
  const std::vector<nlohmann::json> records = readJsonLines(study_.output);
  ASSERT_EQ(records.size(), 8u);
  std::map<std::string, std::set<uint64_t>> seeds;
  for (const nlohmann::json& r : records) {
    const std::string sampler = r.at("sampler").get<std::string>();
    seeds[sampler].insert(r.at("seed").get<uint64_t>());
    // rel_variance comes from a pixel's own samples: only independent ones allow it.
    EXPECT_EQ(r.contains("rel_variance"), sampler == "independent") << r.dump();
    EXPECT_EQ(r.contains("rel_variance_omitted"), sampler == "sobol") << r.dump();
    EXPECT_GT(r.at("rel_mse").get<double>(), 0);
  }
  ASSERT_EQ(seeds.size(), 2u);
  EXPECT_EQ(seeds["independent"].size(), 4u);
  EXPECT_EQ(seeds["sobol"].size(), 4u);
  for (uint64_t seed : seeds["sobol"]) EXPECT_FALSE(seeds["independent"].count(seed)) << seed;
  // A resumed study finds every run, each sampler's under its own key.
  EXPECT_EQ(runConvergenceStudy(study_, nullptr).skipped, 8);

  const Summary summary = summarize(records, "results.jsonl");
  ASSERT_EQ(summary.convergence.size(), 2u) << toJson(summary).dump(1);
  std::set<std::string> rows;
  const nlohmann::json json = toJson(summary);
  for (size_t i = 0; i < summary.convergence.size(); ++i) {
    const ConvergenceGroup& g = summary.convergence[i];
    rows.insert(g.key.sampler);
    EXPECT_EQ(g.runs, 4u);
    const bool omitted = g.key.sampler == "sobol";
    EXPECT_EQ(g.relVarianceOmitted, omitted);
    EXPECT_EQ(std::isnan(g.budgets[0].medianRelVariance), omitted);
    EXPECT_EQ(json["convergence"][i].contains("rel_variance_omitted"), omitted);
    EXPECT_EQ(json["convergence"][i]["budgets"][0]["median_rel_variance"].is_null(), omitted);
  }
  EXPECT_EQ(rows, (std::set<std::string>{"independent", "sobol"}));
  EXPECT_NE(summaryText(summary).find("no rel_variance for the sobol sampler"), std::string::npos)
      << summaryText(summary);
}

TEST_F(SamplerStudy, AnUnknownSamplerIsAnErrorNamingTheOption) {
  study_.samplers = {"independent", "sobl"};
  EXPECT_EQ(errorOf([&] { runConvergenceStudy(study_, nullptr); }),
            "--sampler: unknown sampler \"sobl\" (expected one of independent, stratified, "
            "halton, sobol)");
  EXPECT_FALSE(fs::exists(study_.output));
}

// Records written before samplers were compared lack "sampler": resuming from them is an error
// naming the file, the record and the key, not a key that defaults to "".
TEST_F(SamplerStudy, AResumedRecordWithoutItsSamplerIsAnError) {
  EXPECT_EQ(runConvergenceStudy(study_, nullptr).done, 4);
  std::vector<nlohmann::json> records = readJsonLines(study_.output);
  records[1].erase("sampler");
  std::ofstream out(study_.output, std::ios::trunc);
  for (const nlohmann::json& r : records) out << r.dump() << "\n";
  out.close();
  EXPECT_EQ(errorOf([&] { runConvergenceStudy(study_, nullptr); }),
            study_.output.string() + ": record 2, \"sampler\": missing key");
}

// Ordinary least squares of log y on log x, with the slope's interval at 95% for n = 6 points
// (t = 2.7764451051977987, the 0.975 quantile of Student's t with 4 degrees of freedom),
// written out here rather than taken from fit.h.
struct HandFit {
  double slope, intercept, low, high;
};
HandFit handFit(const std::vector<double>& x, const std::vector<double>& y, double t) {
  const double n = double(x.size());
  double mx = 0, my = 0;
  for (size_t i = 0; i < x.size(); ++i) mx += std::log(x[i]) / n, my += std::log(y[i]) / n;
  double sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
  }
  const double slope = sxy / sxx, intercept = my - slope * mx;
  double sse = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    const double r = std::log(y[i]) - intercept - slope * std::log(x[i]);
    sse += r * r;
  }
  const double se = std::sqrt(sse / (n - 2) / sxx);
  return {slope, intercept, slope - t * se, slope + t * se};
}

nlohmann::json record(const std::string& sampler, int spp, int run, double seconds, double relMse) {
  nlohmann::json r = {{"study", "convergence"},
                      {"scene", "box"},
                      {"width", 8},
                      {"height", 8},
                      {"integrator", "path_tracer_nee"},
                      {"sampler", sampler},
                      {"max_bounces", 5},
                      {"threads", 1},
                      {"budget_type", "spp"},
                      {"budget", spp},
                      {"run", run},
                      {"spp", spp},
                      {"wall_seconds", seconds},
                      {"cpu_seconds", seconds},
                      {"rel_mse", relMse},
                      {"rel_mse_epsilon", 0.01},
                      {"reference_rel_mse", 1e-6}};
  if (sampler == "independent") r["rel_variance"] = relMse;
  return r;
}

TEST(SamplerSummary, EachSamplerIsFittedFromItsOwnRecords) {
  // Two runs at 4, 16 and 64 spp per sampler; relMSE falls as spp^-1 (independent) and
  // spp^-1.5 (sobol), each run off the law by a factor of its own.
  const std::vector<int> spp = {4, 16, 64};
  const std::map<std::string, std::pair<double, std::vector<double>>> laws = {
      {"independent", {1.0, {1.3, 0.8, 1.1, 0.9, 1.25, 0.7}}},
      {"sobol", {1.5, {0.6, 1.4, 1.2, 0.9, 1.05, 0.75}}}};
  std::vector<nlohmann::json> records;
  std::map<std::string, std::vector<double>> xs, ys, meanTime, meanErr;
  for (const auto& [sampler, law] : laws)
    for (size_t b = 0; b < spp.size(); ++b) {
      const double seconds = 0.01 * spp[b];  // the same in both runs: the mean is exact
      double sum = 0;
      for (int run = 0; run < 2; ++run) {
        const double err = 0.5 * std::pow(spp[b], -law.first) * law.second[2 * b + run];
        records.push_back(record(sampler, spp[b], run, seconds, err));
        xs[sampler].push_back(spp[b]);
        ys[sampler].push_back(err);
        sum += err;
      }
      meanTime[sampler].push_back(seconds);
      meanErr[sampler].push_back(sum / 2);
    }
  const Summary summary = summarize(records, "synthetic.jsonl");
  ASSERT_EQ(summary.convergence.size(), 2u);
  for (const ConvergenceGroup& g : summary.convergence) {
    const std::string sampler = g.key.sampler;
    SCOPED_TRACE(sampler);
    const HandFit f = handFit(xs.at(sampler), ys.at(sampler), 2.7764451051977987);
    EXPECT_EQ(g.fitSpp.n, 6);
    EXPECT_NEAR(g.fitSpp.slope, f.slope, 1e-9);
    EXPECT_NEAR(g.fitSpp.slopeLow, f.low, 1e-9);
    EXPECT_NEAR(g.fitSpp.slopeHigh, f.high, 1e-9);
    // Time to 1e-2 from the line through the three (mean time, mean relMSE) points: t = 12.706
    // for 1 degree of freedom enters only its interval, so the estimate is checked alone.
    const HandFit m = handFit(meanTime.at(sampler), meanErr.at(sampler), 12.706204736174705);
    const TimeToAccuracy& toAccuracy = g.timeToAccuracy[0];
    EXPECT_EQ(toAccuracy.targetRelMse, 1e-2);
    EXPECT_NEAR(toAccuracy.seconds, std::exp((std::log(1e-2) - m.intercept) / m.slope), 1e-9);
    EXPECT_EQ(g.relVarianceOmitted, sampler == "sobol");
  }
  // The text table has a row per sampler with its slope and interval.
  const std::string text = summaryText(summary);
  for (const auto& [sampler, law] : laws) {
    const HandFit f = handFit(xs.at(sampler), ys.at(sampler), 2.7764451051977987);
    const std::string cell = fmt::format("{:.3f} [{:.3f}, {:.3f}]", f.slope, f.low, f.high);
    const size_t row = text.find("path_tracer_nee  " + sampler);
    ASSERT_NE(row, std::string::npos) << text;
    EXPECT_NE(text.substr(row, text.find('\n', row) - row).find(cell), std::string::npos)
        << cell << "\n"
        << text;
  }
}

}  // namespace
}  // namespace verity::studies
