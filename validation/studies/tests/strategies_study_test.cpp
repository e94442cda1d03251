// The strategies study at two budgets on a 24×24 Cornell box (all Lambertian, one area light,
// pinhole camera: every strategy (s, t) can sample every path of its length, so each
// unweighted strategy image is an unbiased estimate of its length's image on every pixel it
// reaches).
//
// Checked per record: every strategy of the layout has its relative variances, the weighted
// shares add up to 1, each unweighted strategy's mean agrees with BDPT's length-k image r_k
// (an independent render) on the pixels where r_k is non-zero, and at one bounce (direct
// light) the MIS combination is no noisier than the best single strategy. (Over the pixels a
// strategy itself reached, the agreement fails for (0, 3), which hits the small light from
// few pixels at 16 spp: keeping only those pixels biases its mean upward, 0.65 against 0.12.)
//
// Agreement: the two means are independent, each with a standard error that bounds its own
// (strategy_variance.h), so |difference| ≤ 5 · sqrt(se_u² + se_r²) fails an unbiased pair
// with probability under 6e-7 per strategy if the means are normal (means of 576 pixels ×
// spp samples), under 3e-5 for the test's 40 pairs. Runs are seeded, so the outcome is
// deterministic; a wrong strategy (a missing 1/pdf, a misplaced splat) moves a mean by far more.
//
// MIS against the best strategy: for the balance heuristic with n_i samples of strategy i,
// Veach 1997, Theorem 9.2 bounds its variance by any other combination's, strategy i on its
// own included, plus (1 / min n_i − 1 / Σ n_i) μ²: here one sample per strategy of three, so
// (2/3) μ² per sample, at most (2/3) / spp in relative variance (μ² / (μ² + ε) < 1).
// BDPT's strategies share their subpaths, which the theorem does not assume, so the margin is
// a guide. The term is not small: on the 64×64 Cornell box at 64 spp the balance heuristic's
// direct light is 3× as noisy as (1, 2) (light sampling) alone, within the bound, because it
// gives the noisier light tracing (2, 1) half of the weight.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "validation/studies/json_lines.h"
#include "validation/studies/strategies.h"

namespace verity::studies {
namespace {

namespace fs = std::filesystem;

TEST(StrategiesStudy, PerStrategyVariancesAtTwoBudgets) {
  const fs::path dir =
      fs::path(testing::TempDir()) / ("verity-strategies-budgets-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  StrategiesConfig config;
  config.scene = fs::path(VERITY_SOURCE_DIR) / "scenes" / "cornell-box.json";
  config.budgets = {4, 16};
  config.resolution = 24;
  config.maxBounces = 3;
  config.output = dir / "strategies.jsonl";
  EXPECT_EQ(runStrategiesStudy(config, nullptr).done, 2);
  EXPECT_EQ(runStrategiesStudy(config, nullptr).skipped, 2);
  const std::vector<nlohmann::json> records = readJsonLines(config.output);
  ASSERT_EQ(records.size(), 2u);
  for (const nlohmann::json& r : records) {
    const int spp = r["spp"].get<int>();
    SCOPED_TRACE(fmt::format("{} spp", spp));
    ASSERT_EQ(r["strategies"].size(), 14u);  // (s, t) with s + t − 2 ≤ 3, t ≥ 1
    ASSERT_EQ(r["lengths"].size(), 4u);
    EXPECT_EQ(r["path_tracer"]["spp"].get<int>(), spp);
    EXPECT_EQ(r["bdpt_lengths"]["spp"].get<int>(), spp);
    double total = 0;
    double bestSingle = INFINITY;
    for (const nlohmann::json& st : r["strategies"]) {
      SCOPED_TRACE(fmt::format("({}, {})", st["s"].get<int>(), st["t"].get<int>()));
      total += st["share"].get<double>();
      EXPECT_GT(st["pixels"].get<int>(), 0);
      EXPECT_LE(st["pixels_reached"].get<int>(), st["pixels"].get<int>());
      const double weighted = st["rel_variance_weighted"].get<double>();
      const double unweighted = st["rel_variance_unweighted"].get<double>();
      EXPECT_TRUE(std::isfinite(weighted) && weighted >= 0) << weighted;
      EXPECT_TRUE(std::isfinite(unweighted) && unweighted > 0) << unweighted;
      const double difference =
          st["unweighted_mean"].get<double>() - st["length_mean"].get<double>();
      const double se = std::hypot(st["unweighted_standard_error"].get<double>(),
                                   st["length_standard_error"].get<double>());
      EXPECT_LE(std::abs(difference), 5 * se) << st.dump();
      if (st["bounces"] == 1) bestSingle = std::min(bestSingle, unweighted);
    }
    EXPECT_NEAR(total, 1.0, 1e-4);
    for (const nlohmann::json& k : r["lengths"]) {
      EXPECT_TRUE(std::isfinite(k["rel_variance"].get<double>()));
      EXPECT_TRUE(std::isfinite(k["path_tracer_rel_variance"].get<double>()));
    }
    const double mis = r["lengths"][1]["rel_variance"].get<double>();
    EXPECT_LE(mis, bestSingle + 2.0 / 3.0 / spp) << "MIS " << mis << ", best single " << bestSingle;
    EXPECT_TRUE(r.contains("strategy_images") == (spp == 16));
  }
  EXPECT_TRUE(fs::exists(dir / records[1]["strategy_images"].get<std::string>()));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace verity::studies
