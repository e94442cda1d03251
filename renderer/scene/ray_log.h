// The rays a scene traced, in order: a benchmark replays them on their own to measure what
// the ray queries of a render cost apart from everything else the integrator does.
#pragma once

#include <mutex>
#include <vector>

#include "core/ray.h"

namespace verity {

struct LoggedRay {
  Ray ray;
  bool shadow = false;  // traced with Scene::occluded, not Scene::intersect
};

class RayLog {
 public:
  void add(const Ray& ray, bool shadow) {
    std::lock_guard<std::mutex> lock(mutex_);
    rays_.push_back({ray, shadow});
  }
  const std::vector<LoggedRay>& rays() const { return rays_; }

 private:
  std::mutex mutex_;
  std::vector<LoggedRay> rays_;
};

}  // namespace verity
