// What a density with single-precision steps costs a check on equal-probability cells, beside
// its smooth twin: the modified Phong lobe (n + 1)/(2π)·cosⁿα about a direction 30° from the
// pole, its pdf computed in float (cos α near 1 moves in steps of 6·10⁻⁸, so the lobe is a
// staircase of relative steps n·6·10⁻⁸: a renderer's BSDF in single precision) or in double,
// sampled exactly in double. Each round checks both at the checks' defaults (10⁶ samples, all
// threads), one after the other; prints the median wall-clock seconds, the ratio, and the
// density evaluations and verdict of one more check of each, counted apart from the timed ones
// (a shared counter slows the threads).
//
//   chi2_staircase_bench [exponent (10⁴)] [rounds (5)]
#include <verity/chi2/significance.h>
#include <verity/chi2/warp_adapter.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numbers>
#include <vector>

namespace {

using Eigen::Vector3d;
using namespace verity::chi2;

std::atomic<long long> evaluations{0};
bool counting = false;

template <class Real>
WarpModel phongLobe(double n) {
  const Vector3d axis(0.5, 0, std::sqrt(0.75));
  const Vector3d t = Vector3d(0, 1, 0).cross(axis).normalized(), b = axis.cross(t);
  auto sample = [=](const Uniform2& u) -> Vector3d {
    const double c = std::pow(u.x, 1 / (n + 1)), s = std::sqrt(std::max(0.0, 1 - c * c));
    const double phi = 2 * std::numbers::pi * u.y;
    return (s * std::cos(phi) * t + s * std::sin(phi) * b + c * axis).normalized();
  };
  auto pdf = [=](const Vector3d& w) {
    if (counting) ++evaluations;
    const Real c = Real(w.x()) * Real(0.5) + Real(w.z()) * Real(std::sqrt(0.75));
    if (!(c > 0)) return 0.0;
    return (n + 1) / (2 * std::numbers::pi) * static_cast<double>(std::pow(c, Real(n)));
  };
  return sphereWarp<Vector3d>(sample, pdf);
}

struct Run {
  double seconds = 0;
  long long evaluations = 0;
  std::string verdict;
};

Run check(const WarpModel& model, bool count) {
  CheckOptions options;
  options.name = "Phong lobe";
  options.significance = 0.01;
  evaluations = 0;
  counting = count;
  const auto start = std::chrono::steady_clock::now();
  const CheckResult r = checkWarp(model, options);
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  return {took.count(), evaluations.load(), verdictName(r.verdict())};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

}  // namespace

int main(int argc, char** argv) {
  const double n = argc > 1 ? std::atof(argv[1]) : 1e4;
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 5;
  if (!(n > 0) || rounds < 1) {
    std::cerr << "usage: chi2_staircase_bench [exponent > 0] [rounds ≥ 1]\n";
    return 2;
  }
  const WarpModel smooth = phongLobe<double>(n), steps = phongLobe<float>(n);
  std::vector<double> smoothSeconds, stepSeconds;
  Run a, b;
  for (int k = 0; k < rounds; ++k) {
    smoothSeconds.push_back(check(smooth, false).seconds);
    stepSeconds.push_back(check(steps, false).seconds);
  }
  a = check(smooth, true);
  b = check(steps, true);
  const double ts = median(smoothSeconds), tf = median(stepSeconds);
  std::cout << "Phong lobe n = " << n << ", " << rounds << " rounds, median seconds\n"
            << "  double: " << ts << " s, " << a.evaluations << " evaluations, " << a.verdict
            << "\n  float:  " << tf << " s, " << b.evaluations << " evaluations, " << b.verdict
            << "\n  float / double: " << tf / ts << " in time, "
            << double(b.evaluations) / double(a.evaluations) << " in evaluations\n";
}
