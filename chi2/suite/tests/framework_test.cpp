// Unit tests of the framework's parts against values known independently of this code.
#include <gtest/gtest.h>
#include <verity/chi2/chi_square.h>
#include <verity/chi2/domain.h>
#include <verity/chi2/integral_check.h>
#include <verity/chi2/quadrature.h>

#include <numbers>

#include "chi2/suite/suite.h"
#include "chi2/suite/suite_significance.h"

namespace verity::chi2 {

TEST(FrameworkSignificance, SidakKeepsTheFamilyLevel) {
  // (1 − α)^m must give back 1 − α_family.
  const double a = sidakLevel(0.01, 1000);
  EXPECT_NEAR(std::pow(1 - a, 1000), 0.99, 1e-12);
  EXPECT_NEAR(sidakLevel(0.01, 1), 0.01, 1e-15);
  EXPECT_GE(declaredTestCount(), 2 * 600);
}

TEST(FrameworkChiSquare, KnownQuantile) {
  // Two cells with expectation 50/50 and counts 60/40: X² = 4, one degree of freedom,
  // p = P(χ²₁ > 4) = erfc(√2) = 0.0455003.
  const ChiSquareResult r = chiSquareTest({50, 50}, {60, 40}, 1e-12);
  EXPECT_DOUBLE_EQ(r.statistic, 4.0);
  EXPECT_EQ(r.dof, 1);
  EXPECT_NEAR(r.pValue, std::erfc(std::sqrt(2.0)), 1e-9);
}

TEST(FrameworkChiSquare, PoolsSmallCellsAndKeepsThePool) {
  // Cells expecting 1, 2, 3 pool into one cell of 6, which is kept.
  const ChiSquareResult r = chiSquareTest({1, 2, 3, 94}, {1, 2, 3, 94}, 1e-12);
  EXPECT_EQ(r.pooledCells, 3);
  EXPECT_EQ(r.regularCells, 2);
  EXPECT_DOUBLE_EQ(r.pooledExpected, 6);
  // A pool below 5 is merged into the smallest regular cell, not dropped: 10 samples in
  // cells expecting 0.5 each add (10 − 1)²/... to the statistic.
  const ChiSquareResult s = chiSquareTest({0.5, 0.5, 49, 50}, {5, 5, 40, 50}, 1e-12);
  EXPECT_EQ(s.regularCells, 2);
  EXPECT_NEAR(s.statistic, 0.0, 1e-12);  // (50 vs 50) and (49+1 vs 40+10)
}

TEST(FrameworkChiSquare, SampleWhereTheDensityIsZeroFailsOutright) {
  const ChiSquareResult r = chiSquareTest({0, 500, 500}, {1, 500, 499}, outrightThreshold(1e-3, 3));
  EXPECT_EQ(r.outrightSamples, 1);
  EXPECT_FALSE(r.passed(1e-3));
}

TEST(FrameworkIntegral, FlagsTooLowAndTooHigh) {
  const double a = perTestSignificance();
  // The seed report's figures: integral 0.978916 with 91% valid, 1.04291 with 99%
  // (6.5M samples in its test).
  EXPECT_FALSE(checkIntegral(0.978916, 6'500'000, 5'915'000, a).passed);
  EXPECT_FALSE(checkIntegral(1.04291, 6'500'000, 6'435'000, a).passed);
  // Too low with every sample valid; too high with every sample valid.
  EXPECT_FALSE(checkIntegral(0.995, 1'000'000, 1'000'000, a).passed);
  EXPECT_FALSE(checkIntegral(1.005, 1'000'000, 1'000'000, a).passed);
  // Agreement passes, within the binomial bound plus the quadrature tolerance.
  EXPECT_TRUE(checkIntegral(1.0, 1'000'000, 1'000'000, a).passed);
  EXPECT_TRUE(checkIntegral(0.5, 1'000'000, 500'300, a).passed);
  // 0.5 ± 4.4σ·0.0005 = 0.5022 is beyond the bound at α ≈ 4e-6 (z ≈ 4.6)… and 6σ surely is.
  EXPECT_FALSE(checkIntegral(0.5, 1'000'000, 503'000, a).passed);
}

TEST(FrameworkQuadrature, DiskAndTriangleSupports) {
  // The area of the unit disk and of the triangle, cell by cell over their bounding squares.
  for (auto [domain, area] :
       {std::pair{diskDomain(7), std::numbers::pi}, std::pair{triangleDomain(7), 0.5}}) {
    double total = 0;
    for (const CellIntegral& c : integrateGrid([](double, double) { return 1.0; }, domain, {}))
      total += c.value;
    // To the quadrature's stated relative tolerance (QuadratureOptions::relTolerance).
    EXPECT_NEAR(total, area, QuadratureOptions{}.relTolerance * area) << domain.name();
  }
  // A narrow Gaussian lobe (σ = 0.002) inside one cell of width 0.1 is found.
  const double s = 0.002;
  const Domain d = squareDomain(10);
  double total = 0;
  for (const CellIntegral& c : integrateGrid(
           [s](double x, double y) {
             const double r2 = (x - 0.4321) * (x - 0.4321) + (y - 0.5678) * (y - 0.5678);
             return std::exp(-r2 / (2 * s * s)) / (2 * std::numbers::pi * s * s);
           },
           d, {}))
    total += c.value;
  EXPECT_NEAR(total, 1.0, 1e-6);
}

TEST(FrameworkQuadrature, ErrorEstimateIsInTheIntegralsUnits) {
  // √x on [0, w]: the square-root edge keeps the Gauss–Kronrod difference far from zero, so
  // the estimate must bound the true error; and, being in the integral's units, it shrinks
  // with the interval like the error does (w^1.5), instead of staying at the rule's
  // [−1, 1] figure.
  for (double w : {2.0, 0.02, 2e-4}) {
    double error = 0;
    const double value = integrate1D([](double x) { return std::sqrt(x); }, 0, w, {}, &error);
    const double truth = 2.0 / 3 * std::pow(w, 1.5);
    const double trueError = std::fabs(value - truth);
    EXPECT_GE(error, trueError) << "w = " << w;
    EXPECT_LE(error, 1e-6 * truth)
        << "w = " << w << ": estimate " << error << ", true error " << trueError;
  }
}

TEST(FrameworkDomain, ConeTangentPointsBoundTheConesAzimuths) {
  // A cone of half-angle 20° about an axis 50° from the pole: its tangent points lie on the
  // cone, meridians just inside them cross it twice and meridians just outside never.
  const Vector3d axis = sphereDirection(1.0, std::cos(50 * std::numbers::pi / 180));
  const double cosAngle = std::cos(20 * std::numbers::pi / 180);
  const std::vector<Point2d> points = coneTangentPoints(axis, cosAngle);
  ASSERT_EQ(points.size(), 2u);
  for (const Point2d& p : points) {
    EXPECT_NEAR(sphereDirection(p.x(), p.y()).dot(axis), cosAngle, 1e-12);
    const double inward = p.x() < 1.0 ? 1e-6 : -1e-6;
    EXPECT_EQ(coneCrossings(axis, cosAngle, p.x() + inward).size(), 2u);
    EXPECT_TRUE(coneCrossings(axis, cosAngle, p.x() - inward).empty());
  }
  // A cone that holds the pole spans every azimuth: no tangent points.
  EXPECT_TRUE(coneTangentPoints(axis, std::cos(60 * std::numbers::pi / 180)).empty());
}

TEST(FrameworkDomain, ConeAzimuthsAreWhereTheMeridiansCrossingsPassAHeight) {
  // The same cone, which spans cos θ from cos 70° to cos 30°: at each height between, its two
  // azimuths lie on it, and the meridian there crosses the cone at that height. Heights
  // above and below meet it nowhere.
  const Vector3d axis = sphereDirection(1.0, std::cos(50 * std::numbers::pi / 180));
  const double cosAngle = std::cos(20 * std::numbers::pi / 180);
  for (double z : {0.35, 0.5, 0.64, 0.86}) {
    const std::vector<double> phis = coneAzimuths(axis, cosAngle, z);
    ASSERT_EQ(phis.size(), 2u) << "z " << z;
    for (double phi : phis) {
      EXPECT_GE(phi, 0);
      EXPECT_LT(phi, 2 * std::numbers::pi);
      EXPECT_NEAR(sphereDirection(phi, z).dot(axis), cosAngle, 1e-12) << "z " << z;
      const std::vector<double> zs = coneCrossings(axis, cosAngle, phi);
      EXPECT_TRUE(
          std::any_of(zs.begin(), zs.end(), [z](double c) { return std::fabs(c - z) < 1e-9; }))
          << "z " << z << ", phi " << phi;
    }
  }
  for (double z : {-0.5, 0.33, 0.87}) EXPECT_TRUE(coneAzimuths(axis, cosAngle, z).empty()) << z;
  // A cone about the pole meets a circle of latitude everywhere or nowhere: no azimuth.
  EXPECT_TRUE(coneAzimuths(Vector3d::UnitZ(), 0.5, 0.5).empty());
}

TEST(FrameworkDomain, DirectionAtLastAzimuthIsTheDirection) {
  // Runs of one azimuth, as an inner integral asks, then a new azimuth, a return to an
  // earlier one, and 0 (the kept azimuth's starting value) after others.
  const double calls[][2] = {{0.0, 0.5}, {0.0, -0.9}, {1.3, 0.2}, {1.3, 0.7},   {1.3, -1.0},
                             {4.0, 0.1}, {1.3, 0.2},  {0.0, 0.3}, {6.2, 0.999}, {6.2, 0.0}};
  for (const auto& [phi, z] : calls)
    EXPECT_EQ(sphereDirectionAtLastAzimuth(phi, z), sphereDirection(phi, z))
        << "phi " << phi << ", z " << z;
}

TEST(FrameworkSuite, AtLeast600Configurations) {
  const size_t n =
      suite::warpCases().size() + suite::microfacetCases().size() + suite::bsdfCases().size();
  EXPECT_GE(n, 600u);
  std::set<std::string> names;
  for (const auto& c : suite::bsdfCases()) EXPECT_TRUE(names.insert(c.name).second) << c.name;
}

}  // namespace verity::chi2
