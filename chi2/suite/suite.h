// The suite's configurations: every sampling test, with its parameters, its unique name
// (the GoogleTest parameter name and the source of its seed) and whether it belongs to the
// quick subset. The total number of statistical checks, which fixes the Šidák level, is
// counted from these lists.
#pragma once

#include <verity/chi2/sampling_check.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "chi2/suite/bsdf_subject.h"
#include "chi2/suite/light_subjects.h"
#include "chi2/suite/microfacet_checks.h"
#include "chi2/suite/warp_subjects.h"

namespace verity::chi2::suite {

// `verity chi2`'s check of one material: 64 × 32 cells in (φ, cos θ) and 10⁶ samples (about
// 500 samples per cell where the density is uniform).
inline constexpr int kSphereResolution = 32;
inline constexpr long long kSamples = 1'000'000;

// The sweep's question, asked of every configuration: a 2% density error over cells holding a
// quarter of the mass, found with 90% probability at the suite's level (power.h). The cells
// are of equal probability under the claimed pdf, 32 × 16 on the sphere and 16 × 16 on a
// plane (511 and 255 dof: about 1.06·10⁶ and 0.8·10⁶ valid samples; 64 × 32 would need
// 2.0·10⁶), and the check draws what the target needs, at most kSweepBudget; a configuration
// whose valid samples are too rare for that budget states its weaker power by name
// (BsdfCase::weaker).
inline constexpr double kSweepDensityError = 0.02;
inline constexpr int kSweepSphereResolution = 16;
inline constexpr int kSweepPlanarResolution = 16;
inline constexpr long long kSweepBudget = 4'000'000;
// A BSDF's comparisons (four eval() and one pdf() call per sample, more than drawing it) on
// the first 5·10⁵ samples: a defect touching 4.6·10⁻⁶ of the samples is met with 90%
// probability (TestOptions::auditedSamples).
inline constexpr long long kComparedSamples = 500'000;

struct WarpCase {
  std::string name;
  WarpKind kind;
  float parameter = 0;
  bool quick = true;
};

struct MicrofacetCase {
  std::string name;
  MicrofacetType type;
  float alpha;
  MicrofacetSampling sampling;
  double incidence;  // degrees
  bool quick = false;
  MicrofacetDistribution distribution() const { return {type, alpha, sampling}; }
  Vector3f wi() const { return incidentDirection(incidence, false); }
};

struct BsdfCase {
  std::string name;
  std::string json;      // the material, as the scene format writes it
  double incidence = 0;  // degrees from the geometric normal +z
  bool inside = false;   // wi below the surface (rough dielectric)
  bool rotated = false;  // shading normal normalize(0.25, 0.5, 1)
  bool quick = false;
  CellLayout cells = CellLayout::EqualProbability;
  int resolution = kSweepSphereResolution;  // cells in cos θ, twice as many in φ
  // The degrees of freedom the cells must keep (0: no such claim). A narrow lobe's equal
  // cells are there to keep them, which a grid's few cells take away (docs/checks.md).
  int minDof = 0;
  // Why the configuration cannot find the sweep's target within kSweepBudget, where it
  // cannot: it then draws the budget and states the error it could find (reports/chi2-power.md).
  std::string weaker;
};

// An area light sampled from a reference point (see light_subjects.h).
struct LightCase {
  std::string name;
  LightSetup setup;
  bool quick = true;
};

// GoogleTest prints a case by its name.
inline void PrintTo(const WarpCase& c, std::ostream* os) {
  *os << c.name;
}
inline void PrintTo(const MicrofacetCase& c, std::ostream* os) {
  *os << c.name;
}
inline void PrintTo(const LightCase& c, std::ostream* os) {
  *os << c.name;
}
inline void PrintTo(const BsdfCase& c, std::ostream* os) {
  *os << c.name << " " << c.json;
}

std::vector<WarpCase> warpCases();
std::vector<MicrofacetCase> microfacetCases();
std::vector<BsdfCase> bsdfCases();
std::vector<LightCase> lightCases();
// The reference (correct) samplers of the broken-sampler tests, which must pass.
int controlCaseCount();

// Two statistical checks (chi-square and pdf integral) per sampling test.
int statisticalCheckCount();

Vector3f rotatedNormal();
std::shared_ptr<const Material> makeMaterial(const std::string& json);
BsdfSetup setupFor(const BsdfCase& c);

TestOptions optionsFor(const std::string& name);
TestResult runWarp(const WarpCase& c);
TestResult runMicrofacet(const MicrofacetCase& c);
TestResult runBsdf(const BsdfCase& c);
TestResult runLight(const LightCase& c);

}  // namespace verity::chi2::suite
