// A baseline: one side's tile moments (tile_moments.h) kept in a JSON file, so that CI renders
// only the new side. The file (documented in docs/referee.md):
//   {"format": "verity-referee-baseline", "version": 1,
//    "scene": "...",             the scene identifier: --scene, or else the command template
//    "command": "...",           the command template that rendered it
//    "renderer_version": "...",  as given with --renderer-version ("" when not)
//    "seed": S,                  render i had seed S + 2i (referee.h)
//    "width": W, "height": H, "tile_size": T, "renders": N,
//    "tiles": [{"x": tx, "y": ty, "mean": [R, G, B], "second_moment": [R, G, B]}, ...]}
// tiles in TileGrid order; per channel, the mean over the N renders of the render's tile value
// (the mean of its pixels in the tile) and the second central moment Σ (x − mean)² / N.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "validation/referee/tile_moments.h"

namespace verity::validation {

struct Baseline {
  std::string scene, command, rendererVersion;
  uint64_t seed = 0;
  TileMoments moments;
};

// Throws VerityError naming the file when it cannot be written.
void saveBaseline(const std::filesystem::path& file, const Baseline& baseline);

// Throws VerityError naming the file and the JSON path of what is missing or wrong.
Baseline loadBaseline(const std::filesystem::path& file);

// Throws VerityError naming the baseline file when it was made for another scene than
// `scene` or with another tile size than `tileSize` (option --tile).
void requireSameSetup(const Baseline& baseline, const std::filesystem::path& file,
                      const std::string& scene, int tileSize);

}  // namespace verity::validation

namespace verity::validation {

// Throws VerityError naming the baseline file when a render of the new side (seed + 2i + 1,
// i < maxRenders) would reuse a seed of the baseline's renders (baseline.seed + 2j): a render
// repeated on both sides is not independent of the other side.
void requireNewSeeds(const Baseline& baseline, const std::filesystem::path& file, uint64_t seed,
                     int maxRenders);

}  // namespace verity::validation
