#include <fmt/format.h>
#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/bsdf_model_subject.h>

namespace verity::chi2 {

CheckResult checkBsdf(const BsdfModel& model, const Eigen::Vector3d& wi,
                      const BsdfCheckOptions& options) {
  BsdfTestSetup setup;
  setup.wi = wi.normalized();
  setup.name =
      fmt::format("{}, wi ({:.4f}, {:.4f}, {:.4f})", options.name.empty() ? "bsdf" : options.name,
                  setup.wi.x(), setup.wi.y(), setup.wi.z());
  setup.resolution = options.resolution > 0 ? options.resolution : 32;
  setup.checkReciprocity = options.checkReciprocity;
  const BsdfModelSubject subject(model, setup);
  CheckResult r = runCheck(subject, options, setup.name);
  r.deltaSamples = subject.deltaSamples();
  // The delta lobes, which the histogram leaves out, on a pass of their own.
  if (r.deltaSamples > 0 || options.delta.statisticalTests() > 0) {
    r.delta = checkDeltaLobes(model, setup.wi, options.delta, options.samples, options.significance,
                              options.seed ? *options.seed : seedFromName(setup.name));
    r.test.deltaLobesChecked = r.delta.deltaSamples > 0;
  }
  return r;
}

}  // namespace verity::chi2
