// The batched forms (DensityBatchFn, BsdfModel's and WarpModel's *Batch callables): a
// model given them is checked exactly as it is point by point (the same cell probabilities
// bit for bit, the same histogram, the same verdict and report), in few calls.
//
// Level: each comparison runs one check of two statistical tests at 1% per test; the tests
// here compare the two paths' figures, not the verdict's power, hence 2·10⁴ samples in few
// cells.
#include <gtest/gtest.h>
#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/partition.h>
#include <verity/chi2/warp_adapter.h>

#include <atomic>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "lambert_toy.h"
#include "phong_toy.h"

namespace verity::chi2 {

namespace {

using phong_toy::Vec3;

BsdfModel phong(phong_toy::Flaw flaw) {
  const phong_toy::Phong p(20.5, flaw);
  return bsdfModel<Vec3>(
      [p](const Vec3& wi, const BsdfUniforms& u) { return p.sample(wi, u.xy.x, u.xy.y); },
      [p](const Vec3& wi, const Vec3& wo) { return p.eval(wi, wo); },
      [p](const Vec3& wi, const Vec3& wo) { return p.pdf(wi, wo); });
}

// The model's own callables behind batched forms that count their calls.
struct Calls {
  std::atomic<int> sample{0}, eval{0}, pdf{0};
  std::atomic<long long> pdfPoints{0};
};

BsdfModel batched(BsdfModel m, Calls& calls) {
  const BsdfModel point = m;
  m.sampleBatch = [point, &calls](const Eigen::Vector3d& wi, const std::vector<BsdfUniforms>& u,
                                  std::vector<std::optional<DirectionSample>>& out) {
    ++calls.sample;
    for (size_t k = 0; k < u.size(); ++k) out[k] = point.sample(wi, u[k]);
  };
  m.evalBatch = [point, &calls](const std::vector<Eigen::Vector3d>& wi,
                                const std::vector<Eigen::Vector3d>& wo,
                                std::vector<Eigen::ArrayXd>& out) {
    ++calls.eval;
    for (size_t k = 0; k < out.size(); ++k)
      out[k] = point.eval(wi[wi.size() == 1 ? 0 : k], wo[wo.size() == 1 ? 0 : k]);
  };
  m.pdfBatch = [point, &calls](const Eigen::Vector3d& wi, const std::vector<Eigen::Vector3d>& wo,
                               std::vector<double>& out) {
    ++calls.pdf;
    calls.pdfPoints += static_cast<long long>(wo.size());
    for (size_t k = 0; k < wo.size(); ++k) out[k] = point.pdf(wi, wo[k]);
  };
  m.sample = nullptr;  // the check must not fall back on the point-by-point forms
  m.pdf = nullptr;
  return m;
}

BsdfCheckOptions options(const std::string& name, CellLayout cells) {
  BsdfCheckOptions o;
  o.name = name;
  o.significance = 0.01;
  o.samples = 20'000;
  o.cells = cells;
  o.resolution = 8;  // 128 cells on the sphere, 64 on a plane: the paths' figures, cheaply
  return o;
}

void expectSame(const CheckResult& a, const CheckResult& b) {
  EXPECT_EQ(a.test.probability, b.test.probability);
  EXPECT_EQ(a.test.observed, b.test.observed);
  EXPECT_EQ(a.test.quadratureError, b.test.quadratureError);
  EXPECT_EQ(a.verdict(), b.verdict());
  EXPECT_EQ(a.test.audit.describe(), b.test.audit.describe());
}

}  // namespace

// The grid's integrals and the equal-probability cells from batches are those of the density
// point by point, bit for bit, from the same points: every point the point-by-point path
// evaluates is evaluated once, in calls of kDensityBatchPoints but for a computation's last
// levels.
TEST(DensityBatches, GiveThePointByPointFiguresFromTheSamePointsInACallPerLevel) {
  const Domain d = sphereDomain(16);
  std::atomic<long long> pointCalls{0};
  const DensityFn f = [&](double x, double y) {
    ++pointCalls;
    return std::exp(-40 * (y - 0.7) * (y - 0.7)) * (1 + x);
  };
  long long batches = 0, batchPoints = 0;
  const DensityBatchFn batch = [&](const std::vector<Point2d>& p, std::vector<double>& v) {
    ++batches;
    batchPoints += static_cast<long long>(p.size());
    for (size_t k = 0; k < p.size(); ++k) v[k] = f(p[k].x(), p[k].y());
  };
  const std::vector<CellIntegral> direct = integrateGrid(f, d, {});
  const long long directCalls = pointCalls.exchange(0);
  const std::vector<CellIntegral> batched = integrateGrid(batch, d, {});
  ASSERT_EQ(batched.size(), direct.size());
  for (size_t c = 0; c < batched.size(); ++c) {
    EXPECT_EQ(batched[c].value, direct[c].value) << c;
    EXPECT_EQ(batched[c].error, direct[c].error) << c;
  }
  EXPECT_EQ(batchPoints, directCalls);
  // Full batches, then a call per refinement level, inner and outer, of the pilot, coarse and
  // verifying rules of the last cells.
  EXPECT_LE(batches, batchPoints / static_cast<long long>(kDensityBatchPoints) + 40);
  EXPECT_GE(batchPoints, 15 * 15 * d.cells());  // each cell's first nested rule at least

  const Domain pointCells = equalProbabilityCells(d, f);
  batches = batchPoints = 0;
  pointCalls = 0;
  const Domain batchCells = equalProbabilityCells(d, batch, {}, {});
  EXPECT_EQ(batchCells.xEdges, pointCells.xEdges);
  EXPECT_EQ(batchCells.yEdges, pointCells.yEdges);
  EXPECT_EQ(pointCalls, batchPoints);  // the batches' points only
  EXPECT_LE(batches, batchPoints / static_cast<long long>(kDensityBatchPoints) + 40);
}

// What the batch function throws (a NumPy callable's exception) leaves the integral, and
// the computations waiting for that batch, every cell's, are freed (the sanitizer build looks
// for leaks).
TEST(DensityBatches, AnExceptionFromTheBatchReachesTheCaller) {
  const Domain d = squareDomain(4);
  int calls = 0;
  const DensityBatchFn failing = [&](const std::vector<Point2d>& p, std::vector<double>& v) {
    if (++calls == 1) throw std::runtime_error("pdf raised");
    std::fill(v.begin(), v.end(), p.empty() ? 0.0 : 1.0);
  };
  EXPECT_THROW(
      {
        try {
          integrateGrid(failing, d, {});
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "pdf raised");
          throw;
        }
      },
      std::runtime_error);
  EXPECT_EQ(calls, 1);
}

TEST(BatchedBsdf, IsCheckedAsThePointByPointModelOnEitherLayout) {
  const Vec3 wi{0.5, 0, std::sqrt(0.75)};
  for (CellLayout cells : {CellLayout::Grid, CellLayout::EqualProbability}) {
    for (phong_toy::Flaw flaw : {phong_toy::Flaw::None, phong_toy::Flaw::NonReciprocal}) {
      const std::string name = "batched phong " + cellLayoutName(cells);
      Calls calls;
      const CheckResult point = checkBsdf(phong(flaw), wi, options(name, cells));
      const CheckResult batch = checkBsdf(batched(phong(flaw), calls), wi, options(name, cells));
      SCOPED_TRACE(batch.report());
      expectSame(point, batch);
      EXPECT_EQ(calls.sample, 1);  // one chunk of 2·10⁴ samples
      EXPECT_EQ(calls.eval, 3);    // the samples both ways, and the cell centres
      // Full batches, and a call per refinement level at the end of the partition and of the
      // cells' integrals.
      EXPECT_LE(calls.pdf, calls.pdfPoints / static_cast<long long>(kDensityBatchPoints) + 80);
    }
  }
}

TEST(BatchedWarp, IsCheckedAsThePointByPointModel) {
  WarpModel m = hemisphereWarp<Vec3>(
      [](const Uniform2& u) { return lambert_toy::cosineHemisphere(u.x, u.y); },
      [](const Vec3& w) { return lambert_toy::cosinePdf(w); });
  std::atomic<int> calls{0};
  std::atomic<long long> points{0};
  WarpModel b = m;
  b.sampleBatch = [m, &calls](const std::vector<Uniform2>& u,
                              std::vector<std::optional<Eigen::Vector3d>>& out) {
    ++calls;
    for (size_t k = 0; k < u.size(); ++k) out[k] = m.sample(u[k]);
  };
  b.pdfBatch = [m, &calls, &points](const std::vector<Eigen::Vector3d>& p, std::vector<double>& v) {
    ++calls;
    points += static_cast<long long>(p.size());
    for (size_t k = 0; k < p.size(); ++k) v[k] = m.pdf(p[k]);
  };
  b.sample = nullptr;
  b.pdf = nullptr;
  CheckOptions o = options("batched cosine hemisphere", CellLayout::EqualProbability);
  expectSame(checkWarp(m, o), checkWarp(b, o));
  EXPECT_LE(calls, points / static_cast<long long>(kDensityBatchPoints) + 81);
}

}  // namespace verity::chi2
