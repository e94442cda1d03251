#include "warp_adapter.h"

#include "warp_subject.h"

namespace verity::chi2 {

CheckResult checkWarp(const WarpModel& model, const WarpCheckOptions& options) {
  const int resolution = options.resolution > 0        ? options.resolution
                         : isDirectional(model.domain) ? 32
                                                       : 40;
  const WarpSubject subject(options.name, model, resolution);
  TestOptions o;
  o.samples = options.samples;
  o.significance = options.significance;
  o.seed = options.seed ? *options.seed : seedFromName(options.name);
  CheckResult r;
  r.test = runSamplingTest(subject, o);
  return r;
}

}  // namespace verity::chi2
