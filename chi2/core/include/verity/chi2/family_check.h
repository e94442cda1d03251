// A BSDF checked over its whole parameter space, as a family: every corner of the box of its
// parameters' accepted ranges and a stratified set of points inside it, each at every incidence
// (and from below for a BSDF that transmits). Every check is sized by one target (`detect`) and
// the family is held at one level by Šidák's correction over every statistical test of every
// configuration, so that a correct BSDF fails anywhere with probability at most that level.
// Defects live at the corners (grazing incidence, the smallest roughness, an index near 1): a
// family makes them the first thing checked, not the last.
#pragma once

#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/check_result.h>
#include <verity/chi2/stochastic_check.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace verity::chi2 {

// One parameter of the family and its range, both ends included: the values the BSDF's
// loader accepts.
struct FamilyParameter {
  std::string name;
  double lo = 0, hi = 1;
  // Interior points spread evenly in log(value), for a range over decades (a roughness from
  // 10⁻³ to 1); needs 0 < lo.
  bool logarithmic = false;
};

struct FamilyConfiguration {
  std::vector<double> values;  // one per parameter, in their order
  bool corner = false;         // a corner of the box, else an interior point
  double incidence = 0;        // degrees from the normal
  bool below = false;          // wi from below the surface
  std::string name;            // "alpha=0.001 eta=3 at 89.9° from above"

  // The incident direction in the local frame, (sin θ, 0, ±cos θ) rounded to single precision
  // and unit there: what a BSDF in float sees is the direction the check's geometry uses.
  Eigen::Vector3d wi() const;
};

struct FamilyOptions {
  // Angles of incidence from the normal, in degrees, in [0, 90]: 90 is exactly grazing
  // (wi.z = cos 90° = 6·10⁻¹⁷).
  std::vector<double> incidences{0, 30, 60, 85, 89.9, 90};
  // Every incidence from below the surface too (a BSDF that transmits).
  bool fromBelow = false;
  // Points inside the box beside its 2^d corners, stratified (a Latin hypercube: each
  // parameter's range cut into this many equal parts, in log where logarithmic, one point in
  // each), drawn from `seed`.
  int interiorPoints = 8;
  uint64_t seed = 1;
  // The family-wise level: the probability that a correct BSDF fails any configuration.
  double level = 0.01;
  // Each configuration's check. Its name and significance are set per configuration (the
  // seed, unless set, follows from the name: a configuration rerun alone draws the same
  // samples); the rest applies to every one. By default each is sized to find a 2% density
  // error over 1/4 of the mass.
  BsdfCheckOptions check = defaultCheck();
  // Where check.delta.eta is unset, each configuration's delta refraction is held to its
  // model's relative index (interiorIndex / exteriorIndex) unless that is 1. Where set, this
  // is called last for each configuration with the configuration, its model and its check
  // options, to adjust them: what depends on the parameters (the delta lobes' expected shares
  // and albedos, which Fresnel's equations give per index), or a renderer's rule (an index
  // within 10⁻³ of 1 turned into a pass-through). It is called for every configuration before
  // any check runs, so that the family's level is split over the tests each configuration's
  // options ask for.
  std::function<void(const FamilyConfiguration& configuration, const BsdfModel& model,
                     BsdfCheckOptions& check)>
      configure;
  // Every configuration checked in the mean-weight mode instead (stochastic_check.h), for a
  // BSDF whose eval and sample weight are random estimates (a layered BSDF evaluated by a
  // random walk). `check` and `configure` then do not apply: `stochasticCheck` sets every
  // configuration's samples, resolution and strata (its name, seed and level are set as above).
  bool stochastic = false;
  StochasticCheckOptions stochasticCheck;

  static BsdfCheckOptions defaultCheck();
};

struct FamilyResult {
  std::vector<FamilyParameter> parameters;
  std::vector<FamilyConfiguration> configurations;
  // One per configuration, in the same order: `results`, or in the mean-weight mode
  // (FamilyOptions::stochastic) `stochasticResults`, the other then empty.
  std::vector<CheckResult> results;
  std::vector<StochasticCheck> stochasticResults;
  double level = 0;         // family-wise
  double perTestLevel = 0;  // Šidák's share of it for each statistical test
  int statisticalTests = 0;

  bool stochastic() const { return !stochasticResults.empty(); }
  Verdict verdictOf(size_t configuration) const;
  int count(Verdict verdict) const;
  // The configurations that failed on per-sample comparisons alone (weight, sample pdf,
  // reciprocity), each within what rounding the directions give there
  // (BsdfCheckOptions::directionRounding): "FAILED (rounding)" in the reports.
  int failedOnlyByRounding() const;
  // PASSED only when every configuration passed; FAILED when any failed; else INCONCLUSIVE.
  Verdict verdict() const;
  bool passed() const { return verdict() == Verdict::Passed; }
  // The configurations, failures first, then the inconclusive ones, then those that passed:
  // each with what failed (the checks, the chi-square statistic, the worst per-sample
  // defect) or why it could not run, and what a passed check could have caught.
  std::string report() const;
  std::string markdown() const;
  std::string json() const;
  // JUnit XML for CI (Jenkins, GitLab), a suite named `suite` with one test case per
  // configuration: FAILED a <failure>, INCONCLUSIVE an <error>, each with its report.
  std::string junit(const std::string& suite) const;
};

// The BSDF at one point of the parameter box (values in the order of the parameters).
using BsdfFamily = std::function<BsdfModel(const std::vector<double>& values)>;

// The configurations checkBsdfFamily runs, in its order: the corners, then the interior
// points, each at every incidence from above, then from below. Throws std::invalid_argument
// naming the parameter or option that is out of range.
std::vector<FamilyConfiguration> familyConfigurations(
    const std::vector<FamilyParameter>& parameters, const FamilyOptions& options);

// Makes every configuration's model and options first (the factory and `configure` are
// called once per configuration, in order), then checks the configurations one after another,
// each on every core (checkBsdf): the result does not depend on the number of threads. Where
// options.check.progress is set, its `check` counts the configurations as they start, out of
// `checks`.
FamilyResult checkBsdfFamily(const BsdfFamily& family,
                             const std::vector<FamilyParameter>& parameters,
                             const FamilyOptions& options = {});

}  // namespace verity::chi2
