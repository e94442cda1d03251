// Holm's procedure against examples worked by hand from its definition (Holm 1979): reject
// H_(1..k−1) where k is the first index with p_(k) > α/(m − k + 1).
#include <gtest/gtest.h>
#include <verity/stats/holm.h>

#include <cmath>
#include <stdexcept>

namespace verity::validation {
namespace {

TEST(Holm, StepsDownUntilTheFirstAcceptance) {
  // m = 4, α = 0.05. Sorted: 0.005 ≤ 0.05/4 = 0.0125 reject; 0.01 ≤ 0.05/3 = 0.01667
  // reject; 0.03 > 0.05/2 = 0.025 stop: 0.03 and 0.04 are kept.
  const HolmResult r = holmBonferroni({0.01, 0.04, 0.03, 0.005}, 0.05);
  EXPECT_EQ(r.rejections, 2);
  EXPECT_EQ(r.rejected, (std::vector<bool>{true, false, false, true}));
  // Adjusted: 4·0.005 = 0.02; max(0.02, 3·0.01) = 0.03; max(0.03, 2·0.03) = 0.06;
  // max(0.06, 1·0.04) = 0.06.
  EXPECT_DOUBLE_EQ(r.adjusted[3], 0.02);
  EXPECT_DOUBLE_EQ(r.adjusted[0], 0.03);
  EXPECT_DOUBLE_EQ(r.adjusted[2], 0.06);
  EXPECT_DOUBLE_EQ(r.adjusted[1], 0.06);
}

TEST(Holm, LaterSmallPValuesAreNotRejectedOnceStopped) {
  // 0.001 ≤ 0.0125 reject; 0.03 > 0.01667 stop; 0.045 would pass its own 0.05 but is kept.
  const HolmResult r = holmBonferroni({0.045, 0.001, 0.04, 0.03}, 0.05);
  EXPECT_EQ(r.rejected, (std::vector<bool>{false, true, false, false}));
  // Adjusted: 0.004, max(0.004, 3·0.03) = 0.09, max(0.09, 2·0.04) = 0.09, max(0.09, 0.045).
  EXPECT_DOUBLE_EQ(r.adjusted[1], 0.004);
  EXPECT_DOUBLE_EQ(r.adjusted[3], 0.09);
  EXPECT_DOUBLE_EQ(r.adjusted[2], 0.09);
  EXPECT_DOUBLE_EQ(r.adjusted[0], 0.09);
}

TEST(Holm, RejectsEverythingWhenEveryStepPasses) {
  // 0.001 ≤ 0.01667, 0.02 ≤ 0.025, 0.021 ≤ 0.05.
  const HolmResult r = holmBonferroni({0.021, 0.02, 0.001}, 0.05);
  EXPECT_EQ(r.rejections, 3);
  EXPECT_DOUBLE_EQ(r.adjusted[2], 0.003);
  EXPECT_DOUBLE_EQ(r.adjusted[1], 0.04);
  EXPECT_DOUBLE_EQ(r.adjusted[0], 0.04);
}

TEST(Holm, IsStricterThanUncorrectedTests) {
  // Each 0.02 is below α = 0.05, but the smallest is above α/3: nothing is rejected.
  const HolmResult r = holmBonferroni({0.02, 0.02, 0.02}, 0.05);
  EXPECT_EQ(r.rejections, 0);
  for (double a : r.adjusted) EXPECT_DOUBLE_EQ(a, 0.06);
}

TEST(Holm, BoundaryIsInclusiveAndAdjustedValuesAreCappedAtOne) {
  // p_(1) = α/m exactly is rejected (p ≤ α/(m − k + 1)); p_(2) = 0.7 > α/1 is kept, its
  // adjusted value max(2·0.025, 1·0.7) = 0.7.
  const HolmResult r = holmBonferroni({0.025, 0.7}, 0.05);
  EXPECT_EQ(r.rejected, (std::vector<bool>{true, false}));
  EXPECT_DOUBLE_EQ(r.adjusted[0], 0.05);
  EXPECT_DOUBLE_EQ(r.adjusted[1], 0.7);
  // 2·0.6 = 1.2 caps at 1, and the running maximum carries 1 to 0.7.
  const HolmResult capped = holmBonferroni({0.7, 0.6}, 0.05);
  EXPECT_DOUBLE_EQ(capped.adjusted[1], 1.0);
  EXPECT_DOUBLE_EQ(capped.adjusted[0], 1.0);
}

TEST(Holm, SingleTestAndEmptyFamily) {
  EXPECT_EQ(holmBonferroni({0.01}, 0.01).rejections, 1);
  EXPECT_EQ(holmBonferroni({0.0100001}, 0.01).rejections, 0);
  EXPECT_EQ(holmBonferroni({}, 0.01).rejections, 0);
}

TEST(Holm, RejectsInvalidInput) {
  EXPECT_THROW(holmBonferroni({0.5, 1.5}, 0.05), std::invalid_argument);
  EXPECT_THROW(holmBonferroni({std::nan("")}, 0.05), std::invalid_argument);
  EXPECT_THROW(holmBonferroni({0.5}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace verity::validation
