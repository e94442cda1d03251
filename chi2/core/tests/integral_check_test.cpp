// The pdf-integral check's line states the level of the interval it used.
#include <gtest/gtest.h>
#include <verity/chi2/integral_check.h>

namespace verity::chi2 {
namespace {

TEST(FrameworkIntegralCheck, TheLineStatesTheIntervalsLevel) {
  const IntegralCheck suite = checkIntegral(0.5, 1000, 500, 1e-6);
  EXPECT_NE(suite.describe().find("99.9999% Clopper-Pearson interval"), std::string::npos)
      << suite.describe();
  const IntegralCheck single = checkIntegral(0.5, 1000, 500, 0.01);
  EXPECT_NE(single.describe().find("99% Clopper-Pearson interval"), std::string::npos)
      << single.describe();
  EXPECT_DOUBLE_EQ(single.confidence, 0.99);
}

}  // namespace
}  // namespace verity::chi2
