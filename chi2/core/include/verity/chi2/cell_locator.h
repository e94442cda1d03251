// The cell of a point in a Domain, found in constant expected time: Domain::cellOf
// binary-searches the edges of equal-probability cells (two searches of unpredictable
// branches per sample, 7% of a default check), where a guide table (Devroye 1986, "Non-Uniform
// Random Variate Generation", §III.2.4, for inverting a discrete CDF) names the first edge
// of each of a few equal-width buckets, and a step or two finds the piece. The answer is
// always Domain::cellOf's: the search runs from the guess to the piece whatever the bucket.
#pragma once

#include <verity/chi2/domain.h>

#include <vector>

namespace verity::chi2 {

class CellLocator {
 public:
  explicit CellLocator(const Domain& d);
  // Domain::cellOf(p), cell for cell.
  int cellOf(const Point2d& p) const;

 private:
  // One sorted list of n + 1 edges, from e[0] to e[n], and its guide.
  struct Pieces {
    const double* edges = nullptr;
    int n = 1;
    double lo = 0, scale = 0;  // bucket = (v − lo)·scale
    std::vector<int> guide;    // the piece holding each bucket's lower end
    void build(const double* e, int pieces);
    int pieceOf(double v) const;
  };
  const Domain& d_;
  Pieces x_;
  std::vector<Pieces> y_;  // strip i's pieces in y
};

}  // namespace verity::chi2
