// One pass of one sample per pixel over 16×16 tiles on a TBB task arena: each pixel gets its
// camera sample plus the splats that land on it, added to a film as one sample. Every random
// number depends only on (seed, pixel, sample index), so a pass's values are the same for any
// thread count or schedule, and any process can render any pass.
#pragma once

#include "core/thread_arena.h"
#include "film/film.h"
#include "integrators/integrator.h"
#include "render/component_images.h"
#include "render/progress.h"

namespace verity {

inline constexpr int kTileSize = 16;

class PassRenderer {
 public:
  // `threads` 0: all cores. `samplesPerPixel` is the render's whole budget (samplers that
  // stratify over the budget need it).
  PassRenderer(const Scene& scene, const Integrator& integrator, const Sampler& prototype,
               const Vector2i& resolution, int samplesPerPixel, int threads);

  // `progress`, if given, advances by one per tile rendered.
  void reportTo(Progress* progress) { progress_ = progress; }

  // Renders sample `pass` of every pixel and adds it to `film` (and to `components`).
  void render(int pass, Film& film, ComponentImages* components = nullptr);

  // Over every pass rendered so far.
  uint64_t rays() const;
  uint64_t invalidSplats() const;
  size_t tiles() const { return tiles_.size(); }

 private:
  struct Tile {
    int x0, y0, x1, y1;
  };

  const Scene& scene_;
  const Integrator& integrator_;
  const Sampler& prototype_;
  Vector2i resolution_;
  int samplesPerPixel_;
  Progress* progress_ = nullptr;
  std::vector<Tile> tiles_;
  std::vector<SampleContext> contexts_;
  // This pass's value of every pixel: its own camera sample plus the splats that land on it.
  // Together they are one independent sample of the pixel, so per-pixel sums of squares give
  // a valid variance for splatting integrators too.
  std::vector<Color3> passValues_;
  std::vector<uint8_t> passValid_;
  ThreadArena arena_;
};

}  // namespace verity
