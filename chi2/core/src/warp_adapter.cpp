#include <verity/chi2/warp_adapter.h>
#include <verity/chi2/warp_subject.h>

#include "on_threads.h"

namespace verity::chi2 {

CheckResult checkWarp(const WarpModel& model, const WarpCheckOptions& options) {
  if (options.threads != 0)
    return onThreads(options, [&](const WarpCheckOptions& o) { return checkWarp(model, o); });
  const int resolution = options.resolution > 0        ? options.resolution
                         : isDirectional(model.domain) ? 32
                                                       : 40;
  const std::string name = options.name.empty() ? "warp" : options.name;
  return runCheck(WarpSubject(name, model, resolution), options, name);
}

}  // namespace verity::chi2
