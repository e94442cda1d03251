#include <verity/chi2/cell_locator.h>

#include <algorithm>

namespace verity::chi2 {

namespace {
// Buckets per piece: with equal-probability edges most buckets fall inside one piece.
constexpr int kBucketsPerPiece = 4;
}  // namespace

void CellLocator::Pieces::build(const double* e, int pieces) {
  edges = e;
  n = pieces;
  lo = e[0];
  const int buckets = kBucketsPerPiece * n;
  const double width = e[n] - e[0];
  scale = width > 0 ? buckets / width : 0;
  guide.resize(buckets);
  int k = 0;
  for (int b = 0; b < buckets; ++b) {
    const double start = lo + width * b / buckets;  // no 0/0 where every edge is one value
    while (k < n - 1 && edges[k + 1] <= start) ++k;
    guide[b] = k;
  }
}

int CellLocator::Pieces::pieceOf(double v) const {
  // The largest k in [0, n − 1] with edges[k] ≤ v, as Domain::cellOf's upper_bound finds it:
  // the guide's guess, moved down where rounding put v's bucket above it, then up past every
  // edge at or below v (equal edges included).
  const double last = static_cast<double>(guide.size() - 1);
  int k = guide[static_cast<size_t>(std::clamp((v - lo) * scale, 0.0, last))];
  while (k > 0 && edges[k] > v) --k;
  while (k < n - 1 && edges[k + 1] <= v) ++k;
  return k;
}

CellLocator::CellLocator(const Domain& d) : d_(d) {
  if (d.uniform()) return;
  x_.build(d.xEdges.data(), d.nx);
  y_.resize(d.nx);
  for (int i = 0; i < d.nx; ++i)
    y_[i].build(d.yEdges.data() + static_cast<size_t>(i) * (d.ny + 1), d.ny);
}

int CellLocator::cellOf(const Point2d& p) const {
  const Domain& d = d_;
  if (d.uniform() || !(p.x() >= d.x0 && p.x() <= d.x1 && p.y() >= d.y0 && p.y() <= d.y1))
    return d.cellOf(p);
  const int i = x_.pieceOf(p.x());
  return y_[i].pieceOf(p.y()) * d.nx + i;
}

}  // namespace verity::chi2
