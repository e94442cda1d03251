#include "bsdf_adapter.h"

#include <fmt/format.h>

#include "bsdf_model_subject.h"

namespace verity::chi2 {

CheckResult checkBsdf(const BsdfModel& model, const Eigen::Vector3d& wi,
                      const BsdfCheckOptions& options) {
  BsdfTestSetup setup;
  setup.wi = wi.normalized();
  setup.name = fmt::format("{}, wi ({:.4f}, {:.4f}, {:.4f})", options.name, setup.wi.x(),
                           setup.wi.y(), setup.wi.z());
  setup.resolution = options.resolution;
  setup.checkReciprocity = options.checkReciprocity;
  const BsdfModelSubject subject(model, setup);
  TestOptions o;
  o.samples = options.samples;
  o.significance = options.significance;
  o.seed = options.seed ? *options.seed : seedFromName(setup.name);
  CheckResult r;
  r.test = runSamplingTest(subject, o);
  r.deltaSamples = subject.deltaSamples();
  return r;
}

}  // namespace verity::chi2
