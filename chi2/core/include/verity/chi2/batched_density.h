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
//
// A pass need not compute again what an earlier pass finished: a sub-computation that met no
// unknown point (an inner integral, a rectangle's integral: quadrature.cpp) had true values
// only, so its result is final. The density a pass is given remembers such results
// (Lookup::remembered) and a later pass takes them as they are; a pass then costs the
// unfinished refinement only, not the whole computation again (10⁶ NumPy samples on
// equal-probability cells: 7 s of re-runs against 0.1 s in NumPy before; docs/python.md).
#pragma once

#include <verity/chi2/quadrature.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace verity::chi2 {

// The density at every point of a batch: values[k] = f(points[k]). Called from the thread
// that called run.
using DensityBatchFn =
    std::function<void(const std::vector<Point2d>& points, std::vector<double>& values)>;

class BatchedDensity {
  struct Memory;

 public:
  // The density one computation is given during a pass. The quadrature finds it behind a
  // DensityFn (std::function::target) to remember its sub-computations' results.
  class Lookup {
   public:
    // What identifies a sub-computation within one computation: its kind, bounds and
    // options, as bit patterns.
    using Key = std::array<uint64_t, 12>;
    struct Result {
      double value = 0, error = 0;
    };

    explicit Lookup(Memory& memory) : memory_(&memory) {}
    double operator()(double x, double y) const;
    // compute(g), g being the density the sub-computation is to call: it answers from the
    // points of the sub-computations sharing its pointsKey (the same integrand at other
    // tolerances), kept between passes (a search among a few dozen values, not among the
    // computation's millions), and notes the unknown ones there. A sub-computation that met
    // no unknown point on this thread, its own or a nested one's, is final: a later pass
    // takes its result as it is. compute must not spread over threads.
    Result remembered(const Key& key, const Key& pointsKey,
                      const std::function<Result(const DensityFn& g)>& compute) const;

   private:
    Memory* memory_;
  };

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
  // Evaluates what the memories asked for, in one batch; false when they asked for nothing.
  bool evaluateMissing(std::vector<Memory>& memories);

  DensityBatchFn batch_;
  long long batches_ = 0, evaluations_ = 0;
};

}  // namespace verity::chi2
