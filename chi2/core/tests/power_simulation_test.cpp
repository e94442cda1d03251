// The power claims checked by simulation (issue: "verdicts that state their strength"). Each
// test-only subject is a correct sampler into which exactly the deviation the check says it
// finds is injected: over cells holding a mass m its density is 1 + ε times the claimed one,
// over other cells holding m it is 1 − ε times it. The check sizes itself for that ε
// (TestOptions::detect) and must then fail in about `power` of the runs; the correct subject
// must fail in about α of them.
//
// Each rate is judged by its exact (Clopper–Pearson) interval over kRuns seeded runs. The file
// makes kIntervals such judgements; each interval is at level 1 − sidakLevel(0.01, kIntervals),
// so that a right formula fails the file with probability at most 1%. With 200 runs the
// detection interval is about ±0.07 wide around 0.9: a formula whose power is really 0.75 or
// less (e.g. w² = m·ε² in place of 2·m·ε², which halves λ) is found with probability above 99%.
#include <gtest/gtest.h>
#include <verity/chi2/sampling_check.h>
#include <verity/chi2/significance.h>

#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <iostream>
#include <numbers>

namespace verity::chi2::power_simulation_test {
namespace {

constexpr int kRuns = 200;
constexpr int kIntervals = 10;
constexpr double kLevel = 0.05;  // the checks' own level: about 10 false failures in 200 runs

struct Rate {
  int hits = 0;
  double lower = 0, upper = 1;
};

Rate rateOf(int hits) {
  using boost::math::binomial_distribution;
  const double half = sidakLevel(0.01, kIntervals) / 2;
  Rate r{hits};
  if (hits > 0) r.lower = binomial_distribution<double>::find_lower_bound_on_p(kRuns, hits, half);
  if (hits < kRuns)
    r.upper = binomial_distribution<double>::find_upper_bound_on_p(kRuns, hits, half);
  return r;
}

// A sampler whose first uniform u₁ selects a set of cells of mass m when u₁ < m and another
// of mass m when u₁ ≥ 1 − m. With probability ε a sample of the second set is moved into the
// first (u₁ shifted by 1 − m, uniform again within it): the injected deviation, exactly 1 ± ε
// over the two sets, provided that each set is a union of cells.
class InjectedSubject : public Subject {
 public:
  enum class Shape {
    Square,       // uniform on [0,1]²: u₁ is x, 8 columns
    Strip,        // uniform on x ∈ [1/2, 5/8), u₁ is y: all mass in one column of 8 cells
    CosineLobe,   // cos θ / π on the hemisphere, u₁ is φ / 2π: 16 columns, 8 rows
    NarrowPhong,  // (n + 1)/2π cosⁿθ, n = 2000: all mass in the top row of 16 cells
  };
  InjectedSubject(Shape shape, double mass, double densityError)
      : shape_(shape), mass_(mass), error_(densityError) {
    domain_ = shape == Shape::CosineLobe || shape == Shape::NarrowPhong ? sphereDomain(8)
                                                                        : squareDomain(8);
  }
  const Domain& domain() const override { return domain_; }
  double pdf(double x, double y) const override {
    switch (shape_) {
      case Shape::Square:
        return 1;
      case Shape::Strip:
        return x >= 0.5 && x < 0.625 ? 8.0 : 0.0;
      case Shape::CosineLobe:
        return y > 0 ? y / std::numbers::pi : 0.0;
      case Shape::NarrowPhong:
        return y > 0 ? (kExponent + 1) / (2 * std::numbers::pi) * std::pow(y, kExponent) : 0.0;
    }
    return 0;
  }
  std::vector<double> breakpointsX() const override {
    return shape_ == Shape::Strip ? std::vector<double>{0.5, 0.625} : std::vector<double>{};
  }
  std::vector<Point2d> peaks() const override {
    return shape_ == Shape::NarrowPhong ? std::vector<Point2d>{{0.0, 1.0}} : std::vector<Point2d>{};
  }
  std::optional<Point2d> sample(pcg32& rng, Audit&) const override {
    double u1 = uniform01(rng);
    const double u2 = uniform01(rng), coin = uniform01(rng);
    if (u1 >= 1 - mass_ && coin < error_) u1 -= 1 - mass_;
    const double phi = 2 * std::numbers::pi * u1;
    switch (shape_) {
      case Shape::Square:
        return Point2d(u1, u2);
      case Shape::Strip:
        return Point2d(0.5 + 0.125 * u2, u1);
      case Shape::CosineLobe:
        return Point2d(phi, std::sqrt(u2));  // cos θ = √u₂ has density 2z on [0, 1]
      case Shape::NarrowPhong:
        return Point2d(phi, std::pow(u2, 1.0 / (kExponent + 1)));
    }
    return std::nullopt;
  }
  std::string describe() const override { return "injected deviation"; }

 private:
  static constexpr double kExponent = 2000;
  Shape shape_;
  double mass_, error_;
  Domain domain_;
};

// The fraction of kRuns seeded runs whose chi-square test fails, each run sized by `target`.
Rate chiSquareFailures(InjectedSubject::Shape shape, const DetectionTarget& target, double injected,
                       const std::string& name) {
  const InjectedSubject subject(shape, target.mass, injected);
  int failures = 0;
  for (int run = 0; run < kRuns; ++run) {
    TestOptions o;
    o.significance = kLevel;
    o.detect = target;
    o.seed = seedFromName(name + " run " + std::to_string(run));
    const TestResult r = runSamplingTest(subject, o);
    EXPECT_TRUE(r.targetReached());
    EXPECT_TRUE(r.quadratureHolds()) << r.report();
    failures += !r.chiSquarePassed();
  }
  return rateOf(failures);
}

struct Case {
  const char* name;
  InjectedSubject::Shape shape;
  double mass, densityError;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

class PowerSimulation : public testing::TestWithParam<Case> {};

TEST_P(PowerSimulation, TheStatedDeviationIsFoundWithTheStatedPower) {
  const Case& c = GetParam();
  const DetectionTarget target{c.densityError, c.mass, 0.9};
  const Rate r = chiSquareFailures(c.shape, target, c.densityError, c.name);
  std::cout << c.name << ": found in " << r.hits << " of " << kRuns << " runs\n";
  EXPECT_LE(r.lower, 0.9) << r.hits << " of " << kRuns << " found";
  EXPECT_GE(r.upper, 0.9) << r.hits << " of " << kRuns << " found";
}

INSTANTIATE_TEST_SUITE_P(
    Subjects, PowerSimulation,
    testing::Values(Case{"square", InjectedSubject::Shape::Square, 0.25, 0.05},
                    Case{"strip", InjectedSubject::Shape::Strip, 0.25, 0.05},
                    Case{"cosine", InjectedSubject::Shape::CosineLobe, 0.25, 0.05},
                    Case{"cosine_sixteenth", InjectedSubject::Shape::CosineLobe, 0.0625, 0.1},
                    Case{"narrow_phong", InjectedSubject::Shape::NarrowPhong, 0.25, 0.05}),
    [](const testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

TEST(PowerSimulationLevel, ACorrectSamplerFailsAtTheLevel) {
  for (const auto shape : {InjectedSubject::Shape::Square, InjectedSubject::Shape::NarrowPhong}) {
    const Rate r = chiSquareFailures(shape, {0.05, 0.25, 0.9}, 0.0,
                                     "null " + std::to_string(static_cast<int>(shape)));
    std::cout << "correct subject: failed " << r.hits << " of " << kRuns << " runs\n";
    EXPECT_LE(r.lower, kLevel) << r.hits << " of " << kRuns << " failed";
    EXPECT_GE(r.upper, kLevel) << r.hits << " of " << kRuns << " failed";
  }
}

// The pdf-integral check's statement: a sampler that succeeds half the time, claimed with a
// pdf that integrates to 1/2 + δ, δ the stated detectable error for this sample count.
class HalfSampler : public Subject {
 public:
  explicit HalfSampler(double success) : success_(success) {}
  const Domain& domain() const override { return domain_; }
  double pdf(double, double) const override { return 0.5; }
  std::optional<Point2d> sample(pcg32& rng, Audit&) const override {
    const Point2d p(uniform01(rng), uniform01(rng));
    if (uniform01(rng) >= success_) return std::nullopt;
    return p;
  }
  std::string describe() const override { return "half sampler"; }

 private:
  double success_;
  Domain domain_ = squareDomain(4);
};

TEST(PowerSimulationIntegral, TheStatedNormalisationErrorIsFoundWithTheStatedPower) {
  constexpr long long kSamples = 20'000;
  const IntegralPower stated = integralPower(0.5, kSamples, kLevel, kIntegralTolerance, 0.9);
  ASSERT_TRUE(stated.tooHigh);
  const HalfSampler subject(0.5 - *stated.tooHigh);
  int failures = 0;
  for (int run = 0; run < kRuns; ++run) {
    TestOptions o;
    o.significance = kLevel;
    o.samples = kSamples;
    o.seed = seedFromName("integral power run " + std::to_string(run));
    failures += !runSamplingTest(subject, o).integral.passed;
  }
  const Rate r = rateOf(failures);
  std::cout << "normalisation error " << *stated.tooHigh << ": found in " << r.hits << " of "
            << kRuns << " runs\n";
  EXPECT_LE(r.lower, 0.9) << r.hits << " of " << kRuns << " found";
  EXPECT_GE(r.upper, 0.9) << r.hits << " of " << kRuns << " found";
}

}  // namespace
}  // namespace verity::chi2::power_simulation_test
