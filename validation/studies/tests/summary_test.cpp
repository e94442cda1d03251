// The time-to-accuracy and equal-time summaries of convergence records, on synthetic runs
// whose relative MSE follows a known law.
#include "validation/studies/summary.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"
#include "testing/error_of.h"

namespace verity::studies {
namespace {

nlohmann::json run(const std::string& integrator, double budget, double seconds, double relMse,
                   int index) {
  return {{"study", "convergence"},
          {"scene", "box"},
          {"width", 16},
          {"height", 16},
          {"integrator", integrator},
          {"sampler", "independent"},
          {"max_bounces", 5},
          {"threads", 2},
          {"budget_type", "time"},
          {"budget", budget},
          {"run", index},
          {"spp", int(100 * seconds)},
          {"wall_seconds", seconds},
          {"cpu_seconds", 2 * seconds},
          {"rel_mse", relMse},
          {"rel_variance", relMse},
          {"rel_mse_epsilon", 0.01},
          {"reference_rel_mse", 1e-6}};
}

const ConvergenceGroup& group(const Summary& summary, const std::string& integrator) {
  for (const ConvergenceGroup& g : summary.convergence)
    if (g.key.integrator == integrator) return g;
  throw std::runtime_error("no group " + integrator);
}

// relMSE = 0.04 / t with multiplicative noise: 1% is reached at 4 s, 0.1% at 40 s.
std::vector<nlohmann::json> records() {
  std::mt19937_64 rng(7);
  std::lognormal_distribution<double> noise(0, 0.05);
  std::vector<nlohmann::json> out;
  for (double t : {0.5, 1.0, 2.0, 4.0, 8.0, 16.0})
    for (int r = 0; r < 5; ++r) {
      out.push_back(run("fast", t, t, 0.04 / t * noise(rng), r));
      out.push_back(run("slow", t, t, 0.4 / t * noise(rng), r));
    }
  return out;
}

TEST(StudySummary, TimeToAccuracyFollowsTheFittedLaw) {
  const Summary summary = summarize(records(), "runs.jsonl");
  const std::vector<TimeToAccuracy>& fast = group(summary, "fast").timeToAccuracy;
  ASSERT_EQ(fast.size(), 2u);
  EXPECT_EQ(fast[0].targetRelMse, 1e-2);
  EXPECT_EQ(fast[0].status, AccuracyStatus::Reached);
  const double seconds = fast[0].seconds;
  EXPECT_NEAR(seconds, 4.0, 4.0 * 0.05);  // 5% noise per run, 30 runs
  EXPECT_LT(fast[0].secondsLow, seconds);
  EXPECT_GT(fast[0].secondsHigh, seconds);
  EXPECT_LE(fast[0].secondsLow, 4.0);
  EXPECT_GE(fast[0].secondsHigh, 4.0);
  // 0.1% needs 40 s, beyond the 16 s measured: not reached, whatever the line says.
  EXPECT_EQ(fast[1].status, AccuracyStatus::NotReached);
  // The slow integrator's 1% needs 40 s too; its errors all lie above 0.1%... and above 1%.
  EXPECT_EQ(group(summary, "slow").timeToAccuracy[0].status, AccuracyStatus::NotReached);
  // summary.json spells them as reports/make_report.py reads them.
  const nlohmann::json json = toJson(summary)["convergence"][0]["time_to_accuracy"];
  EXPECT_EQ(json[0]["status"], "reached");
  EXPECT_EQ(json[0]["seconds_low"], fast[0].secondsLow);
  EXPECT_EQ(json[1]["status"], "not reached");
}

TEST(StudySummary, TargetsAboveEveryErrorAreReachedBeforeTheSmallestBudget) {
  std::vector<nlohmann::json> rs;
  for (double t : {1.0, 2.0, 4.0})
    for (int r = 0; r < 3; ++r) rs.push_back(run("fast", t, t, 1e-4 / t * (1 + 0.01 * r), r));
  const Summary summary = summarize(rs, "runs.jsonl");
  EXPECT_EQ(group(summary, "fast").timeToAccuracy[0].status, AccuracyStatus::BeforeSmallestBudget);
}

TEST(StudySummary, EqualTimeComparesEveryIntegratorAtEachBudget) {
  const Summary summary = summarize(records(), "runs.jsonl");
  ASSERT_EQ(summary.equalTime.size(), 6u);
  const EqualTime& at4 = summary.equalTime[3];
  EXPECT_EQ(at4.key.seconds, 4.0);
  const double fast = at4.integrators.at("fast").meanRelMse;
  const double slow = at4.integrators.at("slow").meanRelMse;
  EXPECT_NEAR(slow / fast, 10, 1.0);
  EXPECT_EQ(at4.integrators.at("fast").runs, 5u);
  EXPECT_GT(at4.integrators.at("fast").relMseStdError, 0);
}

// A record that lacks a key the summary reads, or spells it wrong, is an error naming the
// file, the record and the key, not a run of relative MSE 0.
TEST(StudySummary, AMissingKeyIsAnErrorNamingTheFileRecordAndKey) {
  for (const char* key : {"rel_mse", "wall_seconds", "budget", "threads", "scene", "sampler"}) {
    std::vector<nlohmann::json> rs = records();
    rs[2].erase(key);
    EXPECT_EQ(errorOf([&] { summarize(rs, "runs.jsonl"); }),
              fmt::format("runs.jsonl: record 3, \"{}\": missing key", key));
  }
  std::vector<nlohmann::json> misspelled = records();
  misspelled[4]["relmse"] = misspelled[4]["rel_mse"];
  misspelled[4].erase("rel_mse");
  EXPECT_EQ(errorOf([&] { summarize(misspelled, "runs.jsonl"); }),
            "runs.jsonl: record 5, \"rel_mse\": missing key");
  std::vector<nlohmann::json> wrongType = records();
  wrongType[0]["spp"] = "many";
  EXPECT_EQ(errorOf([&] { summarize(wrongType, "runs.jsonl"); }),
            "runs.jsonl: record 1, \"spp\": expected an integer, found \"many\"");
}

TEST(StudySummary, AStrategyWithoutItsShareIsAnError) {
  nlohmann::json strategies = {
      {"study", "strategies"},
      {"scene", "box"},
      {"width", 8},
      {"height", 8},
      {"max_bounces", 3},
      {"spp", 4},
      {"run", 0},
      {"strategies", {{{"s", 0}, {"t", 2}, {"share", 0.7}}, {{"s", 1}, {"t", 1}, {"sahre", 0.3}}}}};
  EXPECT_EQ(errorOf([&] { summarize(std::vector<nlohmann::json>{strategies}, "shares.jsonl"); }),
            "shares.jsonl: record 1, \"strategies\"[1], \"share\": missing key");
}

}  // namespace
}  // namespace verity::studies
