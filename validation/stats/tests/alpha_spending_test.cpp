// Lan and DeMets' (1983) spending functions: their values at known points, and the looks'
// levels adding up to α, which is what bounds the error over all looks (union bound).
#include <gtest/gtest.h>
#include <verity/stats/alpha_spending.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace verity::validation {
namespace {

TEST(AlphaSpending, ValuesAtKnownPoints) {
  // Pocock-type at t = 1/2: α ln(1 + (e − 1)/2) = 0.05 · 0.620115.
  EXPECT_NEAR(spentLevel(SpendingFunction::Pocock, 0.05, 0.5),
              0.05 * std::log(1 + (std::numbers::e - 1) / 2), 1e-15);
  // O'Brien–Fleming-type at t = 1/2, α = 0.05: 2 − 2Φ(1.959964 · √2) = 2 − 2Φ(2.771808)
  // = 0.0055746 (Lan and DeMets 1983, Table 1, spends 0.0056 at the midpoint).
  EXPECT_NEAR(spentLevel(SpendingFunction::OBrienFleming, 0.05, 0.5), 0.0055746, 1e-6);
  for (SpendingFunction f : {SpendingFunction::Pocock, SpendingFunction::OBrienFleming}) {
    EXPECT_EQ(spentLevel(f, 0.05, 0), 0);
    EXPECT_NEAR(spentLevel(f, 0.05, 1), 0.05, 1e-15);
  }
}

TEST(AlphaSpending, TheLooksSpendExactlyAlphaAndEachSomething) {
  for (SpendingFunction f : {SpendingFunction::Pocock, SpendingFunction::OBrienFleming})
    for (int looks : {1, 2, 6, 11}) {
      double sum = 0;
      for (int k = 1; k <= looks; ++k) {
        const double level = lookLevel(f, 0.01, k, looks);
        EXPECT_GT(level, 0) << spendingName(f) << " look " << k << " of " << looks;
        sum += level;
      }
      EXPECT_NEAR(sum, 0.01, 1e-15) << spendingName(f) << " over " << looks << " looks";
    }
  // Pocock spends more at the first look than at the last; O'Brien–Fleming the reverse.
  EXPECT_GT(lookLevel(SpendingFunction::Pocock, 0.05, 1, 6),
            lookLevel(SpendingFunction::Pocock, 0.05, 6, 6));
  EXPECT_LT(lookLevel(SpendingFunction::OBrienFleming, 0.05, 1, 6),
            lookLevel(SpendingFunction::OBrienFleming, 0.05, 6, 6));
}

TEST(AlphaSpending, BadInputIsRefused) {
  EXPECT_THROW(spendingFunction("linear"), std::invalid_argument);
  EXPECT_EQ(spendingFunction("pocock"), SpendingFunction::Pocock);
  EXPECT_EQ(spendingFunction("obrien-fleming"), SpendingFunction::OBrienFleming);
  EXPECT_THROW(spentLevel(SpendingFunction::Pocock, 0, 0.5), std::invalid_argument);
  EXPECT_THROW(spentLevel(SpendingFunction::Pocock, 0.05, 1.5), std::invalid_argument);
  EXPECT_THROW(lookLevel(SpendingFunction::Pocock, 0.05, 0, 3), std::invalid_argument);
  EXPECT_THROW(lookLevel(SpendingFunction::Pocock, 0.05, 4, 3), std::invalid_argument);
}

}  // namespace
}  // namespace verity::validation
