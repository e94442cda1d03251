#include <tbb/parallel_for.h>
#include <verity/chi2/batched_density.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <mutex>
#include <vector>

namespace verity::chi2 {

// The values one computation was given, sorted by the points' bit patterns (a lookup is a
// binary search, and a pass's new values are merged in without an allocation per point), and
// the points it asked for that were unknown. The values are read concurrently during a pass
// and written only between passes.
struct BatchedDensity::Memory {
  struct Entry {
    uint64_t x, y;
    double value;
    bool operator<(const Entry& o) const { return x != o.x ? x < o.x : y < o.y; }
  };
  static Entry entry(double x, double y) {
    return {std::bit_cast<uint64_t>(x), std::bit_cast<uint64_t>(y), 0};
  }

  std::vector<Entry> known, missing;
  std::mutex mutex;  // a computation may call f from several threads

  double lookup(double x, double y) {
    const Entry e = entry(x, y);
    const auto it = std::lower_bound(known.begin(), known.end(), e);
    if (it != known.end() && it->x == e.x && it->y == e.y) return it->value;
    std::lock_guard lock(mutex);
    missing.push_back(e);
    return 0;
  }
};

bool BatchedDensity::evaluateMissing(std::vector<Memory>& memories) {
  // Each memory's points once, in an order that does not depend on the threads' scheduling.
  std::vector<Point2d> points;
  for (Memory& m : memories) {
    std::sort(m.missing.begin(), m.missing.end());
    m.missing.erase(
        std::unique(m.missing.begin(), m.missing.end(),
                    [](const auto& a, const auto& b) { return a.x == b.x && a.y == b.y; }),
        m.missing.end());
    for (const Memory::Entry& e : m.missing)
      points.emplace_back(std::bit_cast<double>(e.x), std::bit_cast<double>(e.y));
  }
  if (points.empty()) return false;
  std::vector<double> values(points.size());
  batch_(points, values);
  ++batches_;
  evaluations_ += static_cast<long long>(points.size());
  size_t next = 0;
  for (Memory& m : memories) {
    if (m.missing.empty()) continue;
    for (Memory::Entry& e : m.missing) e.value = values[next++];
    const auto middle = m.known.insert(m.known.end(), m.missing.begin(), m.missing.end());
    std::inplace_merge(m.known.begin(), middle, m.known.end());
    m.missing.clear();
  }
  return true;
}

void BatchedDensity::run(const std::function<void(const DensityFn& f)>& compute) {
  std::vector<Memory> memory(1);
  const DensityFn f = [&memory](double x, double y) { return memory[0].lookup(x, y); };
  do compute(f);
  while (evaluateMissing(memory));
}

void BatchedDensity::run(int count, const std::function<void(int task, const DensityFn& f)>& task) {
  std::vector<Memory> memories(count);
  std::vector<char> done(count, 0);
  do {
    tbb::parallel_for(0, count, [&](int i) {
      if (done[i]) return;
      Memory& m = memories[i];
      task(i, [&m](double x, double y) { return m.lookup(x, y); });
      if (m.missing.empty()) {
        done[i] = 1;
        m.known = {};  // its result is final
      }
    });
  } while (evaluateMissing(memories));
}

}  // namespace verity::chi2
