// A check's report and data do not depend on how many threads ran it: the samples come from
// streams fixed per block of samples, the cells and integrals per cell, and the audit's
// examples are merged in block order. Each subject runs on 1, 2 and 3 threads (a task arena
// of that size, oversubscribed where the machine has fewer cores); everything but the
// seconds must be identical, including a failing subject's examples of its defects.
//
// Deterministic: no statistical level is at stake here, only equality.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>
#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/figure_data.h>
#include <verity/chi2/significance.h>

#include <atomic>
#include <cmath>
#include <numbers>
#include <regex>
#include <thread>

#include "phong_toy.h"

namespace verity::chi2 {
namespace thread_count_test {
namespace {

using phong_toy::Flaw;
using phong_toy::Vec3;

// The report and the figure's data without the seconds, which are the only thread-dependent
// figures.
std::string withoutSeconds(const CheckResult& r) {
  const std::string report = std::regex_replace(r.report(), std::regex(R"(in [0-9.]+ s)"), "");
  const std::string data = std::regex_replace(
      figureJson(r.test), std::regex(R"("phases":\{[^}]*\},?|"seconds":[^,}]*,?)"), "");
  return report + "\n" + data;
}

CheckResult checkOn(int threads, Flaw flaw, CellLayout cells) {
  const phong_toy::Phong p(20.5, flaw);
  const BsdfModel model = bsdfModel<Vec3>(
      [p](const Vec3& wi, const BsdfUniforms& u) { return p.sample(wi, u.xy.x, u.xy.y); },
      [p](const Vec3& wi, const Vec3& wo) { return p.eval(wi, wo); },
      [p](const Vec3& wi, const Vec3& wo) { return p.pdf(wi, wo); });
  BsdfCheckOptions o;
  o.name = "threads phong";
  o.significance = sidakLevel(0.01, kStatisticalTestsPerCheck);
  o.samples = 300'000;  // five blocks of samples
  o.cells = cells;
  const double t = 40 * std::numbers::pi / 180;
  tbb::task_arena arena(threads);
  return arena.execute([&] { return checkBsdf(model, Vec3{std::sin(t), 0, std::cos(t)}, o); });
}

}  // namespace

TEST(ThreadCount, ReportsAndDataAreTheSameOnOneTwoAndThreeThreads) {
  struct Case {
    Flaw flaw;
    CellLayout cells;
  };
  // A correct lobe on both layouts; a wrong weight (per-sample examples and worst ratios from
  // every block); NaN away from the lobe (the pdf's examples from the quadrature's threads).
  for (const Case& c :
       {Case{Flaw::None, CellLayout::EqualProbability}, Case{Flaw::None, CellLayout::Grid},
        Case{Flaw::Weight, CellLayout::Grid}, Case{Flaw::UnclampedLobe, CellLayout::Grid}}) {
    const CheckResult one = checkOn(1, c.flaw, c.cells);
    const std::string expected = withoutSeconds(one);
    for (int threads : {2, 3})
      EXPECT_EQ(withoutSeconds(checkOn(threads, c.flaw, c.cells)), expected)
          << threads << " threads, flaw " << static_cast<int>(c.flaw) << ", cells "
          << cellLayoutName(c.cells);
    EXPECT_EQ(one.test.audit.clean(), c.flaw == Flaw::None) << one.report();
  }
}

// CheckOptions::threads: with 1 the model's functions are called on the calling thread alone
// (as a library that binds state to a thread needs), with 2 the check has another thread too;
// the report and data are those of a check run in an arena of that size.
TEST(ThreadCount, OneThreadCallsTheModelOnTheCallingThreadAlone) {
  const phong_toy::Phong p(20.5, Flaw::None);
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<long long> elsewhere = 0;
  const auto note = [&] { elsewhere += std::this_thread::get_id() != caller; };
  const BsdfModel model = bsdfModel<Vec3>(
      [&](const Vec3& wi, const BsdfUniforms& u) {
        note();
        return p.sample(wi, u.xy.x, u.xy.y);
      },
      [&](const Vec3& wi, const Vec3& wo) {
        note();
        return p.eval(wi, wo);
      },
      [&](const Vec3& wi, const Vec3& wo) {
        note();
        return p.pdf(wi, wo);
      });
  BsdfCheckOptions o;
  o.name = "threads phong";
  o.significance = sidakLevel(0.01, kStatisticalTestsPerCheck);
  o.samples = 300'000;
  o.cells = CellLayout::EqualProbability;
  const double t = 40 * std::numbers::pi / 180;
  const Vec3 wi{std::sin(t), 0, std::cos(t)};
  o.threads = 1;
  const CheckResult one = checkBsdf(model, wi, o);
  EXPECT_EQ(elsewhere.load(), 0);
  EXPECT_EQ(withoutSeconds(one), withoutSeconds(checkOn(1, Flaw::None, o.cells)));
  o.threads = 2;
  const CheckResult two = checkBsdf(model, wi, o);
  EXPECT_EQ(withoutSeconds(two), withoutSeconds(one));
  // The count sees other threads where TBB has any: the test above can fail.
  if (tbb::this_task_arena::max_concurrency() > 1) EXPECT_GT(elsewhere.load(), 0);
  o.threads = -1;
  EXPECT_THROW(checkBsdf(model, wi, o), std::invalid_argument);
}

}  // namespace thread_count_test
}  // namespace verity::chi2
