// CellLocator (cell_locator.h), the binning's guide-table search, names the cell
// Domain::cellOf names for every point: on edges, a float step either side of them, at equal
// edges (cells of no width), in pieces many times wider than the rest, and on equal-probability
// cells of a narrow lobe.
#include <gtest/gtest.h>
#include <verity/chi2/cell_locator.h>
#include <verity/chi2/partition.h>

#include <cmath>
#include <numbers>
#include <pcg_random.hpp>

namespace verity::chi2 {
namespace {

// Every edge of d, the values a step either side of each, the corners, and random points.
std::vector<Point2d> probes(const Domain& d, uint64_t seed) {
  std::vector<double> xs{d.x0, d.x1}, ys{d.y0, d.y1};
  for (int i = 0; i <= d.nx; ++i) xs.push_back(d.xEdge(i));
  for (int i = 0; i < d.nx; ++i)
    for (int j = 0; j <= d.ny; ++j) ys.push_back(d.yEdge(i, j));
  const size_t nx = xs.size(), ny = ys.size();
  for (size_t k = 0; k < nx; ++k)
    for (double to : {-INFINITY, INFINITY}) xs.push_back(std::nextafter(xs[k], to));
  for (size_t k = 0; k < ny; ++k)
    for (double to : {-INFINITY, INFINITY}) ys.push_back(std::nextafter(ys[k], to));
  std::vector<Point2d> p;
  pcg32 rng(seed);
  const auto u = [&] { return std::ldexp(double(rng()), -32); };
  for (double x : xs)
    for (int k = 0; k < 8; ++k) p.emplace_back(x, ys[rng(static_cast<uint32_t>(ys.size()))]);
  for (double y : ys)
    for (int k = 0; k < 8; ++k) p.emplace_back(xs[rng(static_cast<uint32_t>(xs.size()))], y);
  for (int k = 0; k < 100000; ++k)
    p.emplace_back(d.x0 + (d.x1 - d.x0) * u(), d.y0 + (d.y1 - d.y0) * u());
  return p;
}

void expectSameCells(const Domain& d, uint64_t seed) {
  const CellLocator locator(d);
  long long checked = 0;
  for (const Point2d& p : probes(d, seed)) {
    ASSERT_EQ(locator.cellOf(p), d.cellOf(p)) << "at (" << p.x() << ", " << p.y() << ")";
    ++checked;
  }
  EXPECT_GT(checked, 100000);
}

TEST(CellLocator, NamesDomainsCellOnEdgesEqualEdgesAndUnevenPieces) {
  Domain d;
  d.nx = 5;
  d.ny = 4;
  d.x0 = -1;
  d.x1 = 3;
  // A piece holding 97% of the width, two of no width, and edges closer than a bucket.
  d.xEdges = {-1, -0.99, -0.99, -0.99, -0.98, 3};
  d.yEdges.clear();
  for (int i = 0; i < d.nx; ++i) {
    const std::vector<double> strip = i % 2 ? std::vector<double>{0, 1e-9, 1e-9, 0.5, 1}
                                            : std::vector<double>{0, 0.25, 0.5, 0.75, 1};
    d.yEdges.insert(d.yEdges.end(), strip.begin(), strip.end());
  }
  d.y0 = 0;
  d.y1 = 1;
  expectSameCells(d, 1);
  // Edges on the guide's bucket boundaries (four buckets a piece: twentieths here), where a
  // point a step below an edge can round into the bucket above it.
  d.x0 = 0;
  d.x1 = 1;
  d.xEdges = {0, 0.35, 0.4, 0.45, 0.7, 1};
  expectSameCells(d, 4);
}

TEST(CellLocator, NamesDomainsCellOnEqualProbabilityCellsOfANarrowLobe) {
  // A lobe of width 0.02 in cos θ about the pole, at φ 1: most cells crowd into a sliver.
  const DensityFn f = [](double phi, double z) {
    const double dz = (1 - z) / 0.02, dphi = (phi - 1) / 0.5;
    return std::exp(-dz - dphi * dphi);
  };
  const Domain cells = equalProbabilityCells(sphereDomain(16), f);
  ASSERT_FALSE(cells.uniform()) << cells.gridReason;
  expectSameCells(cells, 2);
}

TEST(CellLocator, TheUniformGridIsDomainsOwn) {
  expectSameCells(sphereDomain(8), 3);
}

}  // namespace
}  // namespace verity::chi2
