// Where a computation (task.h) gets its density values: point by point from a DensityFn, each
// request answered at once, or from a DensityBatchFn, where every computation that asks waits
// and the points that all of them asked for are evaluated in one call, once they are
// kDensityBatchPoints or nothing else can run. The same points are evaluated as point by
// point, each once, with the same results.
#pragma once

#include <tbb/parallel_for.h>
#include <verity/chi2/quadrature.h>

#include <algorithm>
#include <array>
#include <coroutine>
#include <type_traits>
#include <vector>

#include "task.h"

// GCC 12 gives a coroutine's frame linkage even where the coroutine has none, then warns that
// the frame holds a type of the anonymous namespace (as the quadrature's and the partition's
// own records are): a false warning for every computation these files define.
#pragma GCC diagnostic ignored "-Wsubobject-linkage"

namespace verity::chi2 {

class Density {
 public:
  explicit Density(const DensityFn& f) : point_(&f) {}
  explicit Density(const DensityBatchFn& batch) : batch_(&batch) {}
  Density(const Density&) = delete;
  Density& operator=(const Density&) = delete;

  // co_await at(points, values, n): values[k] = f(points[k]) for k < n.
  struct Request {
    Density& density;
    const Point2d* points;
    double* values;
    size_t n;

    bool await_ready() const {
      if (!density.point_) return false;
      for (size_t k = 0; k < n; ++k) values[k] = (*density.point_)(points[k].x(), points[k].y());
      return true;
    }
    void await_suspend(std::coroutine_handle<> waiting) {
      density.wait(points, values, n, waiting);
    }
    void await_resume() const {}
  };
  Request at(const Point2d* points, double* values, size_t n) { return {*this, points, values, n}; }
  // Batched: `computation` resumes once values[k] = f(points[k]) for k < n.
  void wait(const Point2d* points, double* values, size_t n, std::coroutine_handle<> computation);

  // co_await all(children): the children's results in order. Point by point they run one
  // after the other, or over threads where `parallel` (the cells, strips and first pieces);
  // batched, they run together, so that their requests share batches. An awaiter, not a
  // coroutine: awaiting it costs no frame.
  template <class T>
  auto all(std::vector<Task<T>> children, bool parallel = false) {
    return Children<T, std::vector<Task<T>>>{*this, std::move(children), parallel};
  }
  // The same for two children (a piece's halves), without a vector: an array of two results.
  template <class T>
  auto both(Task<T> first, Task<T> second) {
    return Children<T, std::array<Task<T>, 2>>{*this, {std::move(first), std::move(second)}, false};
  }

  // Runs a computation to its end: at once point by point, or batch by batch.
  template <class T>
  T run(Task<T> task) {
    ready_.push_back(task.handle());
    for (;;) {
      while (!ready_.empty()) {
        const std::coroutine_handle<> h = ready_.back();
        ready_.pop_back();
        h.resume();
      }
      if (points_.size() < kBatchSize && startAnother()) continue;
      if (waiting_.empty()) break;
      evaluate();
    }
    return task.result();
  }

 private:
  // The points a batch gathers before it is evaluated, while computations are left to start:
  // enough to make a NumPy call's own cost (tens of microseconds) small against its points'.
  // Far larger batches cost more than they save: every computation in flight is resumed once
  // per batch, and its frames leave the cache between batches. NumPy Lambertian on
  // equal-probability cells, user seconds over two or three runs on a loaded machine: 2¹⁰
  // 1.44-1.59, 2¹⁴ 1.13-1.43, 2¹⁶ 1.48-1.69, 2¹⁸ 1.67-2.32, every cell at once 1.6-1.7.
  static constexpr size_t kBatchSize = kDensityBatchPoints;

  // Starts the next child of the innermost parallel all() with children not yet started.
  bool startAnother() {
    if (unstarted_.empty()) return false;
    Join& j = *unstarted_.back();
    ready_.push_back(*j.next++);
    if (j.next == j.end) unstarted_.pop_back();
    return true;
  }

  template <class T, class Tasks>
  struct Children {
    Density& density;
    Tasks children;
    bool parallel;
    Join join;
    std::vector<std::coroutine_handle<>> handles;

    bool await_ready() {
      if (!density.point_) return children.empty();
      auto runOne = [&](size_t k) { children[k].handle().resume(); };  // runs to its end
      if (parallel)
        tbb::parallel_for(size_t(0), children.size(), runOne);
      else
        for (size_t k = 0; k < children.size(); ++k) runOne(k);
      return true;
    }
    void await_suspend(std::coroutine_handle<> parent) {
      for (Task<T>& c : children) {
        c.handle().promise().join = &join;
        handles.push_back(c.handle());
      }
      // A parallel all's children start one at a time, as the batch needs more points
      // (startAnother): thousands of cells in flight, each with its refinement's frames, would
      // be touched once per batch far out of cache.
      const size_t started = parallel ? 1 : handles.size();
      join = {children.size(), parent, handles.data() + started, handles.data() + handles.size()};
      for (size_t k = started; k-- > 0;) density.ready_.push_back(handles[k]);
      if (started < handles.size()) density.unstarted_.push_back(&join);
    }
    auto await_resume() {
      if constexpr (std::is_same_v<Tasks, std::vector<Task<T>>>) {
        std::vector<T> results;
        results.reserve(children.size());
        for (Task<T>& c : children) results.push_back(c.result());
        return results;
      } else {
        return std::array<T, 2>{children[0].result(), children[1].result()};
      }
    }
  };
  struct Waiting {
    double* values;
    size_t n;
    std::coroutine_handle<> computation;
  };

  // One call for every point asked for, or one per kMostPerCall of them; the computations that
  // asked are ready again.
  void evaluate();
  // A level of a partition's refinement asks for a few million points. Calls of 2¹⁸ keep a
  // NumPy callable's temporaries (2 MiB each) in cache and its arrays below the size that
  // malloc maps afresh, and zeroes, for every call (NumPy Lambertian on equal-probability
  // cells: system time 0.37-0.42 s -> 0.24-0.29 s, peak memory 449 -> 336 MB).
  static constexpr size_t kMostPerCall = size_t(1) << 18;

  const DensityFn* point_ = nullptr;
  const DensityBatchFn* batch_ = nullptr;
  std::vector<std::coroutine_handle<>> ready_;
  std::vector<Join*> unstarted_;
  std::vector<Point2d> points_;  // the next batch, kept from batch to batch as values_ is
  std::vector<double> values_;
  std::vector<Waiting> waiting_;
};

}  // namespace verity::chi2
