// Checks the example's GGX conductor and concentric disk with Verity's adapters, and checks
// that a deliberately broken variant of each is rejected. Returns non-zero if a correct one
// fails or a broken one passes.
#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/significance.h>
#include <verity/chi2/stochastic_check.h>
#include <verity/chi2/warp_adapter.h>

#include <cmath>
#include <iostream>
#include <string>

#include "concentric_disk.h"
#include "ggx.h"

namespace chi2 = verity::chi2;
using example::Ggx;
using example::Vec2;
using example::Vec3;

// The BSDF as the adapter sees it: three callables in the example's own types.
chi2::BsdfModel model(const Ggx& ggx) {
  return chi2::bsdfModel<Vec3>(
      [ggx](const Vec3& wi, const chi2::BsdfUniforms& u) { return ggx.sample(wi, u.xy.x, u.xy.y); },
      [ggx](const Vec3& wi, const Vec3& wo) { return ggx.eval(wi, wo); },
      [ggx](const Vec3& wi, const Vec3& wo) { return ggx.pdf(wi, wo); });
}

Vec3 incidence(double degrees) {
  const double t = degrees * example::kPi / 180;
  return {std::sin(t), 0, std::cos(t)};
}

int main() {
  // The checks that must pass: three incidences and the disk, two statistical tests each, and
  // the stochastic check below, at a family-wise level of 1%.
  const int correctChecks = 4;
  const double level = chi2::sidakLevel(0.01, chi2::kStatisticalTestsPerCheck * correctChecks +
                                                  chi2::kStatisticalTestsPerStochasticCheck);
  int mistakes = 0;
  auto expect = [&](const chi2::CheckResult& r, bool shouldPass) {
    std::cout << r.report() << "\n\n";
    if (r.passed() != shouldPass) {
      std::cout << "UNEXPECTED: " << (shouldPass ? "a correct one failed" : "a broken one passed")
                << "\n\n";
      ++mistakes;
    }
  };

  const Ggx ggx(0.3, {0.95, 0.64, 0.54});
  for (double degrees : {0.0, 45.0, 80.0}) {
    chi2::BsdfCheckOptions o;
    o.name = "ggx alpha 0.3, " + std::to_string(int(degrees)) + " degrees";
    o.significance = level;
    expect(chi2::checkBsdf(model(ggx), incidence(degrees), o), true);
  }
  chi2::WarpCheckOptions w;
  w.name = "concentric disk";
  w.significance = level;
  expect(chi2::checkWarp(chi2::diskWarp<Vec2>(example::concentricDisk, example::diskPdf), w), true);
  // The mode for a BSDF whose eval and weight are random estimates (a layered BSDF), which a
  // deterministic one passes too; its Welch tests and Holm's procedure are Verity::stats'.
  chi2::StochasticCheckOptions s;
  s.name = "ggx alpha 0.3, 45 degrees, stochastic mode";
  s.significance = level;
  const chi2::StochasticCheck stochastic = chi2::checkStochasticBsdf(model(ggx), incidence(45), s);
  std::cout << stochastic.report() << "\n\n";
  if (!stochastic.passed()) {
    std::cout << "UNEXPECTED: a correct one failed\n\n";
    ++mistakes;
  }

  // The broken variants, at the same level: a pdf without the reflection's Jacobian, and a
  // disk with a linear radius.
  chi2::BsdfCheckOptions broken;
  broken.name = "ggx without the Jacobian";
  broken.significance = level;
  const Ggx wrong(0.3, {0.95, 0.64, 0.54}, /*forgetJacobian=*/true);
  expect(chi2::checkBsdf(model(wrong), incidence(45), broken), false);
  w.name = "disk with a linear radius";
  expect(chi2::checkWarp(chi2::diskWarp<Vec2>(example::linearRadiusDisk, example::diskPdf), w),
         false);

  std::cout << (mistakes ? "FAILED" : "all as expected") << "\n";
  return mistakes ? 1 : 0;
}
