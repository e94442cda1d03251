#include "integrators/component_layout.h"

#include <fmt/format.h>

namespace verity {

namespace {
// Strategies of fewer bounces than k: k + 2 per length (s = 0 … k + 1), two images each.
int strategiesBefore(int bounces) {
  return bounces * (bounces + 3) / 2;
}
}  // namespace

ComponentLayout::ComponentLayout(Kind kind, int maxBounces) : kind_(kind), maxBounces_(maxBounces) {
  for (int k = 0; k <= maxBounces; ++k) {
    if (kind == Kind::PathLengths) {
      components_.push_back({k});
      continue;
    }
    for (int s = 0; s <= k + 1; ++s) {
      components_.push_back({k, s, k + 2 - s, true});
      components_.push_back({k, s, k + 2 - s, false});
    }
  }
}

uint64_t ComponentLayout::sizeFor(Kind kind, int maxBounces) {
  const uint64_t lengths = uint64_t(maxBounces) + 1;
  return kind == Kind::PathLengths ? lengths : lengths * (lengths + 3);
}

int ComponentLayout::pathLengthIndex(int bounces) const {
  if (kind_ != Kind::PathLengths || bounces < 0 || bounces > maxBounces_) return -1;
  return bounces;
}

int ComponentLayout::strategyIndex(int s, int t, bool weighted) const {
  const int k = s + t - 2;
  if (kind_ != Kind::Strategies || s < 0 || t < 1 || k > maxBounces_) return -1;
  return 2 * (strategiesBefore(k) + s) + (weighted ? 0 : 1);
}

std::string ComponentLayout::name(int i) const {
  const Component& c = components_[i];
  if (c.s < 0) return fmt::format("k{}", c.bounces);
  return fmt::format("s{}_t{}_{}", c.s, c.t, c.weighted ? "weighted" : "unweighted");
}

}  // namespace verity
