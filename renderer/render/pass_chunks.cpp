#include "render/pass_chunks.h"

#include <algorithm>

namespace verity {

int renderChunk(PassRenderer& passes, int chunk, int samplesPerPixel, Film& chunkFilm,
                const std::atomic<bool>* cancel, ComponentImages* components) {
  chunkFilm.clear();
  const int first = chunk * kPassesPerChunk;
  const int last = std::min(first + kPassesPerChunk, samplesPerPixel);
  for (int pass = first; pass < last; ++pass) {
    if (cancel && cancel->load()) return pass - first;
    passes.render(pass, chunkFilm, components);
  }
  return last - first;
}

}  // namespace verity
