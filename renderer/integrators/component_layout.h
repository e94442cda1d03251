// The images a render can split its estimate into, besides the image itself:
//   Strategies   one image per BDPT strategy (s, t) with s + t − 2 ≤ max_bounces, twice: its
//                MIS-weighted contribution and its unweighted one (the strategy's estimate
//                of all paths of its length on its own);
//   PathLengths  one image per path length k = 0 … max_bounces (bounces, as max_bounces
//                counts them).
// s counts the light subpath's vertices (the emitter point included) and t the camera
// subpath's (the lens point included): the full path has s + t vertices, s + t − 1 edges and
// k = s + t − 2 bounces. The weighted strategy images, and the path-length images, add up to
// the rendered image.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace verity {

class ComponentLayout {
 public:
  enum class Kind { Strategies, PathLengths };
  struct Component {
    int bounces;
    int s = -1, t = -1;    // the strategy, or −1 for a path-length image
    bool weighted = true;  // false: a strategy's unweighted contribution
  };

  ComponentLayout(Kind kind, int maxBounces);
  // The number of images of a layout, without making it.
  static uint64_t sizeFor(Kind kind, int maxBounces);

  Kind kind() const { return kind_; }
  int maxBounces() const { return maxBounces_; }
  int size() const { return static_cast<int>(components_.size()); }
  const Component& operator[](int i) const { return components_[i]; }
  // Index of an image, or −1 when the layout has none (a path longer than max_bounces).
  int pathLengthIndex(int bounces) const;
  int strategyIndex(int s, int t, bool weighted) const;
  // File name without extension: "k3", "s2_t3_weighted", "s2_t3_unweighted".
  std::string name(int i) const;

 private:
  Kind kind_;
  int maxBounces_;
  std::vector<Component> components_;
};

}  // namespace verity
