// Square tiles over an image, partial tiles at the right and bottom edges; tile (tx, ty) has
// index ty · tilesX + tx.
#pragma once

#include <verity/stats/tile_pooling.h>

#include <algorithm>

namespace verity::validation {

struct TileGrid {
  int width = 0, height = 0, tileSize = 1;

  int tilesX() const { return (width + tileSize - 1) / tileSize; }
  int tilesY() const { return (height + tileSize - 1) / tileSize; }
  int count() const { return tilesX() * tilesY(); }
  TileRect rect(int tx, int ty) const {
    return {tx * tileSize, ty * tileSize, std::min((tx + 1) * tileSize, width),
            std::min((ty + 1) * tileSize, height)};
  }
};

}  // namespace verity::validation
