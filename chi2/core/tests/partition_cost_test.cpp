// What equal-probability cells cost (partition.h), counted in density evaluations, not in
// seconds: the partition evaluates the density no more often than integrating the cells it
// cuts does, smooth or a staircase of single-precision steps.
#include <gtest/gtest.h>
#include <verity/chi2/partition.h>

#include <atomic>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>

namespace verity::chi2 {
namespace {

// The modified Phong lobe (n + 1)/(2π)·cosⁿα about a direction 30° from the pole, zero below
// the horizon, computed in `Real`. In float, cos α near 1 moves in steps of 6·10⁻⁸, so the
// lobe is a staircase of relative steps n·6·10⁻⁸ (6·10⁻⁴ at n = 10⁴): a BSDF of a renderer
// that evaluates in single precision. In double, its smooth twin.
template <class Real>
double phongLobe(double n, double phi, double z) {
  if (z <= 0) return 0;
  const Real zr = static_cast<Real>(z);
  const Real s = std::sqrt(std::max(Real(0), Real(1) - zr * zr));
  const Real c = s * std::cos(static_cast<Real>(phi)) * static_cast<Real>(0.5) +
                 zr * static_cast<Real>(std::sqrt(0.75));
  if (!(c > 0)) return 0;
  return (n + 1) / (2 * std::numbers::pi) * static_cast<double>(std::pow(c, static_cast<Real>(n)));
}

TEST(FrameworkPartitionCost, CutsItsCellsForNoMoreEvaluationsThanIntegratingThem) {
  // A diffuse lobe, a lobe of a few cells and a narrow one on the sphere, and a Gaussian on
  // the square.
  struct Case {
    std::string name;
    Domain grid;
    DensityFn f;
    DensityFeatures features;
  };
  const DensityFeatures horizon{[](double) { return std::vector<double>{0.0}; }, {}, {}, {}};
  const Point2d axis = sphereCoords(Vector3d(0.5, 0, std::sqrt(0.75)));
  const std::vector<Case> cases{
      {"cosine", sphereDomain(32),
       [](double, double z) { return z > 0 ? z / std::numbers::pi : 0.0; }, horizon},
      {"Phong 30", sphereDomain(32), [](double x, double y) { return phongLobe<double>(30, x, y); },
       horizon},
      {"Phong 10^4", sphereDomain(32),
       [](double x, double y) { return phongLobe<double>(1e4, x, y); },
       DensityFeatures{horizon.breaksY, {}, {axis}, {}}},
      // Single-precision staircases: the cells' integrals refine many steps to the depth
      // limit (20 times the evaluations of the smooth twin's), the partition's refinement is
      // bounded.
      {"Phong 10^4 float", sphereDomain(32),
       [](double x, double y) { return phongLobe<float>(1e4, x, y); },
       DensityFeatures{horizon.breaksY, {}, {axis}, {}}},
      {"Phong 10^5 float", sphereDomain(32),
       [](double x, double y) { return phongLobe<float>(1e5, x, y); },
       DensityFeatures{horizon.breaksY, {}, {axis}, {}}},
      {"Gaussian",
       squareDomain(16),
       [](double x, double y) {
         return std::exp(-((x - 0.4) * (x - 0.4) + (y - 0.6) * (y - 0.6)) / (2 * 0.05 * 0.05));
       },
       {}},
  };
  std::map<std::string, long long> integralsOf;
  for (const Case& c : cases) {
    std::atomic<long long> calls{0};
    const DensityFn counted = [&](double x, double y) {
      ++calls;
      return c.f(x, y);
    };
    const Domain cells = equalProbabilityCells(c.grid, counted, c.features);
    const long long partition = calls.exchange(0);
    integrateGrid(counted, cells, QuadratureOptions{}, c.features);
    const long long integrals = calls;
    EXPECT_LE(partition, integrals) << c.name;
    integralsOf[c.name] = integrals;
    std::cout << c.name << ": partition " << partition << " evaluations, cells' integrals "
              << integrals << "\n";
  }
  // A staircase is refined, but not without end: the round-off detector's refinement of
  // noise must die out (quadrature.cpp, bisect). 19.7 times at 2026-11-28; 35.7 with a
  // detector that refused any noisy bisection whose halves' estimates differed by 4 times.
  EXPECT_LE(integralsOf["Phong 10^4 float"], 25 * integralsOf["Phong 10^4"]);
}

}  // namespace
}  // namespace verity::chi2
