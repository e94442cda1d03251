// A density evaluated in batches: one call for many points, for SIMD or GPU code, or a
// density written in Python or NumPy, whose cost is in the call rather than in the point.
//
// The quadrature (quadrature.h) and the equal-probability cells (partition.h) are adaptive:
// which point they ask for next depends on the values they were given. BatchedDensity runs
// such a computation several times, each time with a density that answers from the points
// already evaluated and answers 0 for a point not yet known, noting it. A piece of the
// quadrature whose nodes are all 0 meets its tolerance at once, so each pass asks for the
// nodes of one further refinement level wherever the previous values call for one: every
// node of every cell at that level, in one batch. The pass that asks for no new point ran on
// true values only, so its result is the one the same computation gives with the density
// evaluated point by point, bit for bit (BatchedDensityTest checks it).
#pragma once

#include <verity/chi2/quadrature.h>

#include <functional>
#include <vector>

namespace verity::chi2 {

// The density at every point of a batch: values[k] = f(points[k]). Called from the thread
// that called run.
using DensityBatchFn =
    std::function<void(const std::vector<Point2d>& points, std::vector<double>& values)>;

class BatchedDensity {
 public:
  explicit BatchedDensity(DensityBatchFn batch) : batch_(std::move(batch)) {}

  // One computation that evaluates the density only through f, deterministically; it may
  // call f from several threads. Returns once a pass asked for no unknown point.
  void run(const std::function<void(const DensityFn& f)>& compute);
  // `count` independent computations of that kind (a grid's cells): they run in parallel,
  // each remembering only its own points, and a pass runs again only those that asked for
  // an unknown point.
  void run(int count, const std::function<void(int task, const DensityFn& f)>& task);

  long long batches() const { return batches_; }
  long long evaluations() const { return evaluations_; }

 private:
  struct Memory;
  // Evaluates what the memories asked for, in one batch; false when they asked for nothing.
  bool evaluateMissing(std::vector<Memory>& memories);

  DensityBatchFn batch_;
  long long batches_ = 0, evaluations_ = 0;
};

}  // namespace verity::chi2
