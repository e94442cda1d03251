// Equal-probability cells (partition.h): each cell holds about 1/K of the mass for smooth,
// narrow and partly zero densities; zero regions at the ends keep cells that expect nothing;
// cellOf agrees with the edges; the cells are the same for any thread count.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <verity/chi2/partition.h>
#include <verity/chi2/sampling_check.h>

#include <cmath>
#include <numbers>
#include <pcg_random.hpp>

namespace verity::chi2 {
namespace {

// What a layout gives each cell: ∫ f over it, as the sampling test integrates it.
std::vector<double> probabilities(const Domain& d, const DensityFn& f,
                                  const DensityFeatures& features = {}) {
  std::vector<double> p;
  double total = 0;
  for (const CellIntegral& c : integrateGrid(f, d, QuadratureOptions{}, features)) {
    p.push_back(c.value);
    total += c.value;
  }
  for (double& v : p) v /= total;
  return p;
}

// Every cell that holds mass holds between half and one and a half times its equal share
// (1/K over the K cells of mass): the bound partition.h states.
void expectNearlyEqual(const std::vector<double>& p, int zeroCellsAtMost) {
  int zero = 0;
  for (double v : p) zero += v == 0;
  EXPECT_LE(zero, zeroCellsAtMost);
  const double share = 1.0 / (p.size() - zero);
  for (size_t c = 0; c < p.size(); ++c)
    if (p[c] != 0) {
      EXPECT_GT(p[c], 0.5 * share) << "cell " << c;
      EXPECT_LT(p[c], 1.5 * share) << "cell " << c;
    }
}

// A 2D Gaussian of width σ at `centre`, normalised on the plane.
DensityFn gaussian(Point2d centre, double sigma) {
  return [=](double x, double y) {
    const double r2 = (Point2d(x, y) - centre).squaredNorm();
    return std::exp(-r2 / (2 * sigma * sigma)) / (2 * std::numbers::pi * sigma * sigma);
  };
}

// A Phong-like lobe cosⁿ about a direction 30° from the pole, zero below the horizon: the
// density of a reflection BSDF, narrow for large n.
DensityFn phongLobe(double n) {
  const Vector3d axis(std::sin(std::numbers::pi / 6), 0, std::cos(std::numbers::pi / 6));
  return [=](double phi, double z) {
    if (z <= 0) return 0.0;
    const double c = sphereDirection(phi, z).dot(axis);
    return c > 0 ? (n + 1) / (2 * std::numbers::pi) * std::pow(c, n) : 0.0;
  };
}

TEST(FrameworkPartition, UniformSquareKeepsTheGrid) {
  const Domain d = equalProbabilityCells(squareDomain(8), [](double, double) { return 1.0; });
  ASSERT_FALSE(d.uniform());
  for (int i = 0; i <= 8; ++i) EXPECT_NEAR(d.xEdge(i), i / 8.0, 1e-9);
  expectNearlyEqual(probabilities(d, [](double, double) { return 1.0; }), 0);
}

TEST(FrameworkPartition, SmoothDensityCellsHoldEqualShares) {
  const DensityFn f = [](double x, double y) { return 0.2 + 4 * x * x * y; };
  expectNearlyEqual(probabilities(equalProbabilityCells(squareDomain(10), f), f), 0);
}

TEST(FrameworkPartition, NarrowLobeCellsHoldEqualShares) {
  // σ = 10⁻³: on the 16 × 16 grid the lobe lies in one cell; here every cell holds 1/256.
  const DensityFn f = gaussian({0.37, 0.61}, 1e-3);
  const DensityFeatures features{{}, {}, {Point2d(0.37, 0.61)}, {}};
  const Domain d = equalProbabilityCells(squareDomain(16), f, features);
  // The density underflows to 0 beyond 38σ: a strip on either side, and a cell below and
  // above the lobe in every other strip, expect nothing.
  expectNearlyEqual(probabilities(d, f, features), 2 * 16 + 2 * 14);
  EXPECT_LT(d.xEdge(14) - d.xEdge(2), 0.01);  // the inner strips crowd round the lobe
}

TEST(FrameworkPartition, PhongLobeOnTheSphereKeepsItsCellsAndAZeroHemisphere) {
  // Exponent 10⁴: on the 64 × 32 grid of (φ, cos θ) 4 cells expect 5 of 10⁶ samples.
  const DensityFn f = phongLobe(1e4);
  const DensityFeatures features{[](double) { return std::vector<double>{0.0}; }, {}, {}, {}};
  const Domain d = equalProbabilityCells(sphereDomain(32), f, features);
  const std::vector<double> p = probabilities(d, f, features);
  // Per strip one cell below the lobe (the lower hemisphere and more) and one above it; and
  // one strip where φ is beyond the lobe (the density underflows to 0 there).
  expectNearlyEqual(p, 2 * 64 + 32);
  int zero = 0;
  for (double v : p) zero += v == 0;
  EXPECT_GE(zero, 64);  // the lower hemisphere is covered by cells that expect nothing
  // Each strip's lowest cell starts at the rectangle's edge and expects nothing; in a strip
  // of mass it holds the lower hemisphere.
  for (int i = 0; i < d.nx; ++i) {
    EXPECT_EQ(d.yEdge(i, 0), -1.0);
    EXPECT_EQ(d.yEdge(i, d.ny), 1.0);
    EXPECT_EQ(p[i], 0.0) << "strip " << i;
    double mass = 0;
    for (int j = 0; j < d.ny; ++j) mass += p[j * d.nx + i];
    if (mass > 0) {
      EXPECT_GE(d.yEdge(i, 1), 0.0) << "strip " << i;
    }
  }
}

TEST(FrameworkPartition, ZeroRegionAtAnEndIsACellThatExpectsNothing) {
  // Zero for x < 0.3 and for y > 0.8: a strip and a row of cells that expect nothing.
  const DensityFn f = [](double x, double y) { return x >= 0.3 && y <= 0.8 ? 1.0 + y : 0.0; };
  const DensityFeatures features{[](double) { return std::vector<double>{0.8}; }, {0.3}, {}, {}};
  const Domain d = equalProbabilityCells(squareDomain(8), f, features);
  EXPECT_DOUBLE_EQ(d.xEdge(1), 0.3);
  for (int i = 1; i < 8; ++i) EXPECT_DOUBLE_EQ(d.yEdge(i, 7), 0.8) << "strip " << i;
  expectNearlyEqual(probabilities(d, f, features), 8 + 7);
}

TEST(FrameworkPartition, AHorizonThatMovesAcrossAStripLeavesNoCellTakenForEmpty) {
  // Zero below a horizon that is not declared (a BSDF's horizon in a rotated frame), which
  // crosses y = 1/2 between the last of the rule's nodes in x (0.99573) and the strip's end:
  // every node finds nothing below 1/2, the end finds mass in [0.49, 0.5], a piece of its
  // profile (the pieces are cut at 0.49 and 0.5, as at a density's declared jumps). A cell
  // that expects nothing must hold no mass anywhere, its edges included, or a sample there
  // fails the test outright.
  const auto horizon = [](double x) { return 0.5 + 0.1 * (0.9959 - x); };
  const DensityFn f = [&](double x, double y) { return y > horizon(x) ? 1.0 : 0.0; };
  const DensityFeatures features{[](double) { return std::vector<double>{0.49, 0.5}; }, {}, {}, {}};
  Domain one;  // the unit square as one strip of 8 cells
  one.ny = 8;
  const Domain d = equalProbabilityCells(one, f, features);
  const std::vector<double> p = probabilities(d, f, features);
  for (int j = 0; j < d.ny; ++j) {
    if (p[j] > 0) continue;
    // Across the strip, ends included, and towards each of the cell's y edges in steps that
    // halve.
    for (int u = 0; u <= 64; ++u)
      for (int v = 1; v <= 80; ++v) {
        const double x = static_cast<double>(u) / 64;
        const double lo = d.yEdge(0, j), hi = d.yEdge(0, j + 1);
        const double step = std::ldexp(hi - lo, -v / 2);
        const double y = v % 2 ? lo + step : hi - step;
        ASSERT_EQ(f(x, y), 0.0) << "cell " << j << " [" << lo << ", " << hi << "] at (" << x << ", "
                                << y << ") expects nothing";
      }
  }
  EXPECT_EQ(p[0], 0.0);  // below the horizon
}

TEST(FrameworkPartition, DiskAndTriangleSupportsAreCut) {
  const Domain disk = equalProbabilityCells(diskDomain(8), [](double, double) { return 1.0; });
  expectNearlyEqual(probabilities(disk, [](double, double) { return 1.0; }), 0);
  // Zero (underflow) beyond 38σ: a strip in x and a cell above the lobe in the others.
  const DensityFn g = gaussian({0.2, 0.3}, 0.01);
  const Domain triangle = equalProbabilityCells(triangleDomain(8), g);
  expectNearlyEqual(probabilities(triangle, g), 8 + 7);
}

TEST(FrameworkPartition, ZeroDensityFallsBackToTheGridAndSaysSo) {
  const Domain d = equalProbabilityCells(squareDomain(4), [](double, double) { return 0.0; });
  EXPECT_TRUE(d.uniform());
  EXPECT_NE(d.gridReason.find("integrates to 0"), std::string::npos) << d.gridReason;
  EXPECT_NE(d.name().find("grid (equal-probability cells need mass"), std::string::npos)
      << d.name();
}

TEST(FrameworkPartition, CellOfAgreesWithTheEdges) {
  const DensityFn f = gaussian({0.5, 0.5}, 0.05);
  const Domain d = equalProbabilityCells(squareDomain(12), f);
  pcg32 rng(seedFromName("FrameworkPartition.CellOfAgreesWithTheEdges"));
  for (int k = 0; k < 100'000; ++k) {
    // Half the points on an edge, where the half-open rule decides.
    Point2d p(uniform01(rng), uniform01(rng));
    if (k % 2) p.x() = d.xEdge(static_cast<int>(rng(13)));
    const int c = d.cellOf(p);
    ASSERT_GE(c, 0);
    const CellBounds b = d.cell(c);
    const bool lastX = c % d.nx == d.nx - 1, lastY = c / d.nx == d.ny - 1;
    ASSERT_TRUE(p.x() >= b.x0 && (p.x() < b.x1 || (lastX && p.x() == b.x1)))
        << p.transpose() << " cell " << c;
    ASSERT_TRUE(p.y() >= b.y0 && (p.y() < b.y1 || (lastY && p.y() == b.y1)))
        << p.transpose() << " cell " << c;
  }
  EXPECT_EQ(d.cellOf(Point2d(1.0, 1.0)), d.cells() - 1);
  EXPECT_EQ(d.cellOf(Point2d(1.5, 0.5)), -1);
}

TEST(FrameworkPartition, CellsAreTheSameForAnyThreadCount) {
  const DensityFn f = phongLobe(300);
  const Domain many = equalProbabilityCells(sphereDomain(16), f);
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const Domain single = equalProbabilityCells(sphereDomain(16), f);
  EXPECT_EQ(many.xEdges, single.xEdges);
  EXPECT_EQ(many.yEdges, single.yEdges);
}

TEST(FrameworkPartition, LayoutIsParsedByName) {
  EXPECT_EQ(parseCellLayout("equal"), CellLayout::EqualProbability);
  EXPECT_EQ(parseCellLayout("grid"), CellLayout::Grid);
  EXPECT_EQ(cellLayoutName(CellLayout::Grid), "grid");
  try {
    parseCellLayout("fine", "--cells");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--cells: 'fine' is no cell layout"), std::string::npos);
  }
}

}  // namespace

// A narrow lobe 20° from the pole of the sphere (σ = 10⁻⁴ rad, unit mass: a rough dielectric's
// refraction at α 10⁻⁴ seen from 30°), declared as a peak, in the top row of the grid's
// 32 rows in cos θ (0.9375 to 1). Such a peak was once left to the pole's grading along cos θ,
// which never reached it: the partition's marginal found no mass there, its cells integrated
// to 0, and a rough dielectric's check FAILED outright, its samples where nothing was claimed.
TEST(FrameworkPartition, ANarrowLobeNearThePoleIsFoundAndCut) {
  const double s = 1e-4, theta = 20 * std::numbers::pi / 180, phi = 2.0;
  const Vector3d c = sphereDirection(phi, std::cos(theta));
  const DensityFn lobe = [=](double x, double z) {
    const double d2 = (sphereDirection(x, z) - c).squaredNorm();
    return std::exp(-d2 / (2 * s * s)) / (2 * std::numbers::pi * s * s);
  };
  DensityFeatures features;
  features.peaks = {Point2d(phi, std::cos(theta))};
  const Domain cells = equalProbabilityCells(sphereDomain(32), lobe, features, {});
  double total = 0;
  for (const CellIntegral& cell : integrateGrid(lobe, cells, QuadratureOptions{}, features))
    total += cell.value;
  EXPECT_NEAR(total, 1, 1e-4);
  // As for the lobe on the square: a strip on either side, and a cell below and above the lobe
  // in each of the 62 others, expect nothing.
  expectNearlyEqual(probabilities(cells, lobe, features), 2 * 32 + 2 * 62);
}
}  // namespace verity::chi2
