// The fixed grouping of a render's passes that makes its image independent of how many
// processes render it: passes are taken kPassesPerChunk at a time, each chunk accumulates
// into its own zeroed film, and the image is the chunk films added in chunk order. One
// process does exactly this too; several (distributed/) render different chunks and add them
// in the same order, so the sums, and the image, are the same bits.
#pragma once

#include <atomic>

#include "film/film.h"
#include "render/pass_renderer.h"

namespace verity {

// Four passes per chunk: a chunk film (56 bytes a pixel) sent between processes then costs
// 14 bytes per pixel and pass, about what the pass's own values would, while a 16-spp render
// still splits into 4 chunks and a 2048-spp reference into 512.
inline constexpr int kPassesPerChunk = 4;

inline int chunkCount(int samplesPerPixel) {
  return (samplesPerPixel + kPassesPerChunk - 1) / kPassesPerChunk;
}

// Clears `chunkFilm` and renders chunk `chunk` of a `samplesPerPixel` render into it, stopping
// before a pass when `cancel` is raised. Returns the passes rendered.
int renderChunk(PassRenderer& passes, int chunk, int samplesPerPixel, Film& chunkFilm,
                const std::atomic<bool>* cancel, ComponentImages* components = nullptr);

}  // namespace verity
