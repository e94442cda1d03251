// The power that equal-probability cells add: a narrow lobe centred on a corner of four
// grid cells whose sampler moves mass between the halves of each quadrant in azimuth. Each
// quadrant keeps its quarter of the mass, so the grid's four populated cells see a correct
// multinomial (dof 3) at any sample count; equal-probability cells cut the lobe itself into
// 256 cells and see the defect.
#include <gtest/gtest.h>
#include <verity/chi2/sampling_check.h>
#include <verity/chi2/significance.h>

#include <cmath>
#include <numbers>

namespace verity::chi2 {
namespace {

// An isotropic Gaussian of width σ = 0.002 at (0.5, 0.5) on the unit square's 16 × 16 grid:
// the lobe (±6σ as sampled) lies inside the four cells round the centre. Sampled by radius
// (Rayleigh) and azimuth; `skewed` draws the azimuth inside each quadrant as v² of a uniform
// v, which keeps the quadrant's mass and puts 71% of it in the quadrant's first half.
class QuadrantSkewedLobe : public Subject {
 public:
  explicit QuadrantSkewedLobe(bool skewed) : skewed_(skewed) {}
  const Domain& domain() const override { return domain_; }
  double pdf(double x, double y) const override {
    const double r2 = (Point2d(x, y) - kCentre).squaredNorm();
    return std::exp(-r2 / (2 * kSigma * kSigma)) / (2 * std::numbers::pi * kSigma * kSigma);
  }
  std::optional<Point2d> sample(pcg32& rng, Audit&) const override {
    const double r = kSigma * std::sqrt(-2 * std::log(1 - double(uniform01(rng))));
    const double u = 4 * double(uniform01(rng));
    const double quadrant = std::floor(u), v = u - quadrant;
    const double phi = (quadrant + (skewed_ ? v * v : v)) * std::numbers::pi / 2;
    return kCentre + r * Point2d(std::cos(phi), std::sin(phi));
  }
  std::vector<Point2d> peaks() const override { return {kCentre}; }
  std::string describe() const override {
    return skewed_ ? "Gaussian lobe, azimuth skewed inside each quadrant" : "Gaussian lobe";
  }

 private:
  static constexpr double kSigma = 0.002;
  inline static const Point2d kCentre{0.5, 0.5};
  Domain domain_ = squareDomain(16);
  bool skewed_;
};

// Four tests (two samplers, two layouts) at a family-wise level of 1% (Šidák): each
// chi-square and pdf-integral test at sidakLevel(0.01, 8). With 10⁵ samples in 256
// equal-probability cells (390 expected in each) the skew's non-centrality is in the
// thousands against 255 dof: power indistinguishable from 1 (the statistic below is
// printed); on the grid the skew has no power at all, by construction.
TestResult run(bool skewed, CellLayout cells) {
  TestOptions o;
  o.samples = 100'000;
  o.seed = seedFromName("CellPower " + std::to_string(skewed));  // same samples per layout
  o.significance = sidakLevel(0.01, 2 * 4);
  o.cells = cells;
  return runSamplingTest(QuadrantSkewedLobe(skewed), o);
}

TEST(FrameworkCellPower, EqualProbabilityCellsSeeAnInLobeDefectTheGridCannot) {
  const TestResult grid = run(true, CellLayout::Grid);
  EXPECT_EQ(grid.verdict(), Verdict::Passed) << grid.report();
  EXPECT_EQ(grid.chiSquare.dof, 3) << grid.report();  // four populated cells
  const TestResult equal = run(true, CellLayout::EqualProbability);
  EXPECT_EQ(equal.verdict(), Verdict::Failed) << equal.report();
  EXPECT_GT(equal.chiSquare.dof, 150) << equal.report();  // 16 × 16 less those expecting 0
  std::cout << grid.report() << "\n" << equal.report() << "\n";
}

TEST(FrameworkCellPower, TheRightLobePassesOnBoth) {
  for (CellLayout cells : {CellLayout::Grid, CellLayout::EqualProbability}) {
    const TestResult r = run(false, cells);
    EXPECT_EQ(r.verdict(), Verdict::Passed) << r.report();
  }
}

}  // namespace
}  // namespace verity::chi2
