#include <fmt/format.h>
#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/bsdf_model_subject.h>
#include <verity/chi2/phase_times.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include "on_threads.h"

namespace verity::chi2 {

namespace {

void requireTolerance(double value, const char* option) {
  if (!(value >= 0 && value < 1))
    throw std::invalid_argument(fmt::format(
        "BsdfCheckOptions::{} = {}: a relative tolerance must be in [0, 1)", option, value));
}

}  // namespace

CheckResult checkBsdf(const BsdfModel& model, const Eigen::Vector3d& wi,
                      const BsdfCheckOptions& options) {
  if (options.threads != 0)
    return onThreads(options, [&](const BsdfCheckOptions& o) { return checkBsdf(model, wi, o); });
  requireTolerance(options.weightTolerance, "weightTolerance");
  requireTolerance(options.reciprocityTolerance, "reciprocityTolerance");
  BsdfTestSetup setup;
  // Kept as given where it is unit to single precision, so that a BSDF in float sees the very
  // direction whose geometry the check computes (renormalised in double it would move by 10⁻⁸).
  setup.wi = std::fabs(wi.norm() - 1) <= 1e-7 ? wi : wi.normalized();
  setup.weightTolerance = options.weightTolerance;
  setup.reciprocityTolerance = options.reciprocityTolerance;
  if (!(options.directionRounding >= 0 && options.directionRounding < 0.01))
    throw std::invalid_argument(
        fmt::format("BsdfCheckOptions::directionRounding = {}: must be in [0, 0.01)",
                    options.directionRounding));
  setup.directionRounding = options.directionRounding;
  BsdfModel sized = model;
  if (sized.components == 0) {
    const Eigen::Vector3d mirror(-setup.wi.x(), -setup.wi.y(), setup.wi.z());
    sized.components = static_cast<int>(model.eval(setup.wi, mirror).size());
  }
  setup.name =
      fmt::format("{}, wi ({:.4f}, {:.4f}, {:.4f})", options.name.empty() ? "bsdf" : options.name,
                  setup.wi.x(), setup.wi.y(), setup.wi.z());
  setup.resolution = options.resolution > 0 ? options.resolution : 32;
  setup.checkReciprocity = options.checkReciprocity;
  const BsdfModelSubject subject(std::move(sized), setup);
  CheckResult r = runCheck(subject, options, setup.name);
  r.deltaSamples = subject.deltaSamples();
  // The delta lobes, which the histogram leaves out, on a pass of their own.
  if (r.deltaSamples > 0 || options.delta.statisticalTests() > 0) {
    const PhaseTimer timer(r.test.phases, Phase::DeltaLobes);
    r.delta =
        checkDeltaLobes(model, setup.wi, options.delta, deltaDraws(r.test), options.significance,
                        options.seed ? *options.seed : seedFromName(setup.name));
    r.test.deltaLobesChecked = r.delta.deltaSamples > 0;
  }
  return r;
}

}  // namespace verity::chi2
