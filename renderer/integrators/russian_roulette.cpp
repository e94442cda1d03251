#include "integrators/russian_roulette.h"

#include <algorithm>

#include "sampling/sampler.h"

namespace verity {

bool RussianRoulette::survives(const RouletteHistory& history, const Color3& throughput,
                               Sampler& sampler, float* survival) const {
  *survival = 1;
  if (history.nonDeltaEvents < depth_) return true;
  const float q = std::min(1.0f, maxComponent(throughput) * history.etaScale / threshold_);
  // A path that carries nothing ends without drawing a sample. The path tracer relies on
  // this (it does not stop at a zero throughput before); the subpath walk of BDPT and the
  // light tracer already ends at one, so for it this test never fires.
  if (!(q > 0)) return false;
  *survival = std::max(q, kMinSurvival);
  return sampler.next1D() < *survival;
}

}  // namespace verity
