// BatchRegions' batches from a film, apart from batch_regions.cpp so that this, which needs the
// renderer, stays out of the array-based verity_compare_core.
#include "validation/compare/batch_regions.h"

namespace verity::validation {

void BatchRegions::addBatch(const Film& film) {
  addBatch(film.width(), film.height(), [&](int x, int y) { return film.mean(x, y); });
}

}  // namespace verity::validation
