#include <tbb/parallel_for.h>
#include <verity/chi2/batched_density.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace verity::chi2 {

namespace {

// Unknown points met on this thread: a sub-computation that ran on one thread and saw this
// unchanged met none.
thread_local long long missesHere = 0;

struct Entry {
  uint64_t x, y;
  double value;
  bool operator<(const Entry& o) const { return x != o.x ? x < o.x : y < o.y; }
  bool operator==(const Entry& o) const { return x == o.x && y == o.y; }
};
Entry entry(double x, double y) {
  return {std::bit_cast<uint64_t>(x), std::bit_cast<uint64_t>(y), 0};
}

// Values sorted by the points' bit patterns (a lookup is a binary search, and a pass's new
// values are merged in without an allocation per point).
struct Values {
  std::vector<Entry> known;

  const Entry* find(const Entry& e) const {
    const auto it = std::lower_bound(known.begin(), known.end(), e);
    return it != known.end() && *it == e ? &*it : nullptr;
  }
  void merge(std::vector<Entry>& added) {
    const auto middle = known.insert(known.end(), added.begin(), added.end());
    // A sub-computation's few dozen points are sorted in place: inplace_merge would allocate.
    if (known.size() < 256)
      std::sort(known.begin(), known.end());
    else
      std::inplace_merge(known.begin(), middle, known.end());
  }
};

// Each point once, in an order that does not depend on the threads' scheduling.
void sortUnique(std::vector<Entry>& points) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
}

struct KeyHash {
  size_t operator()(const BatchedDensity::Lookup::Key& key) const {
    uint64_t h = 0xcbf29ce484222325;  // FNV-1a over the words
    for (uint64_t w : key) h = (h ^ w) * 0x100000001b3;
    return static_cast<size_t>(h ^ (h >> 29));
  }
};

// What a sub-computation left in a pass: its result, or the points it found unknown.
struct Outcome {
  BatchedDensity::Lookup::Key key, pointsKey;
  bool finished = false;
  BatchedDensity::Lookup::Result result;
  std::vector<Entry> missing;
};

}  // namespace

// What one computation was given: the values of the points it asked for directly and of
// its sub-computations' points (by points key), the results of those finished, and what this
// pass left unknown or finished. All but the last are read concurrently during a pass and
// written only between passes.
struct BatchedDensity::Memory {
  Values direct;
  std::vector<Entry> missing;
  std::unordered_map<Lookup::Key, Values, KeyHash> values;
  std::unordered_map<Lookup::Key, Lookup::Result, KeyHash> results;
  std::vector<Outcome> outcomes;
  std::mutex mutex;  // a computation may call f from several threads

  double lookup(double x, double y) {
    const Entry e = entry(x, y);
    if (const Entry* known = direct.find(e)) return known->value;
    ++missesHere;
    std::lock_guard lock(mutex);
    missing.push_back(e);
    return 0;
  }
  // The points to evaluate, and the list where each one's value goes; results finished are
  // kept.
  void collect(std::vector<Point2d>& points, std::vector<std::vector<Entry>*>& into) {
    auto add = [&](std::vector<Entry>& list) {
      sortUnique(list);
      for (const Entry& e : list)
        points.emplace_back(std::bit_cast<double>(e.x), std::bit_cast<double>(e.y));
      into.insert(into.end(), list.size(), &list);
    };
    add(missing);
    std::erase_if(outcomes, [&](const Outcome& o) {
      if (o.finished) results.emplace(o.key, o.result);
      return o.finished;
    });
    // Sub-computations sharing a points key asked for their points together.
    std::sort(outcomes.begin(), outcomes.end(),
              [](const Outcome& a, const Outcome& b) { return a.pointsKey < b.pointsKey; });
    for (size_t k = 0, first = 0; k < outcomes.size(); ++k) {
      if (outcomes[k].pointsKey != outcomes[first].pointsKey) first = k;
      if (first == k) continue;
      std::vector<Entry>& list = outcomes[first].missing;
      list.insert(list.end(), outcomes[k].missing.begin(), outcomes[k].missing.end());
      outcomes[k].missing.clear();
    }
    for (Outcome& o : outcomes) add(o.missing);
  }
  // The values evaluated, from the lists they were asked in.
  void keep() {
    direct.merge(missing);
    missing.clear();
    for (Outcome& o : outcomes)
      if (!o.missing.empty()) values[o.pointsKey].merge(o.missing);
    outcomes.clear();
  }
  // This pass met no unknown point: the computation's result is final.
  bool complete() const {
    return missing.empty() && std::all_of(outcomes.begin(), outcomes.end(),
                                          [](const Outcome& o) { return o.finished; });
  }
  void forget() {
    direct = {};
    values = {};
    results = {};
    outcomes = {};
  }
};

double BatchedDensity::Lookup::operator()(double x, double y) const {
  return memory_->lookup(x, y);
}

BatchedDensity::Lookup::Result BatchedDensity::Lookup::remembered(
    const Key& key, const Key& pointsKey,
    const std::function<Result(const DensityFn& g)>& compute) const {
  if (const auto it = memory_->results.find(key); it != memory_->results.end()) return it->second;
  const auto it = memory_->values.find(pointsKey);
  const Values* record = it == memory_->values.end() ? nullptr : &it->second;
  Outcome outcome{key, pointsKey};
  const long long before = missesHere;
  const Result result = compute([&](double x, double y) {
    const Entry e = entry(x, y);
    if (record)
      if (const Entry* known = record->find(e)) return known->value;
    ++missesHere;
    if (outcome.missing.empty()) outcome.missing.reserve(64);  // a level of rules at once
    outcome.missing.push_back(e);
    return 0.0;
  });
  if (missesHere == before) {
    outcome.finished = true;
    outcome.result = result;
  } else if (outcome.missing.empty()) {
    return result;  // only nested sub-computations met unknown points
  }
  std::lock_guard lock(memory_->mutex);
  memory_->outcomes.push_back(std::move(outcome));
  return result;
}

bool BatchedDensity::evaluateMissing(std::vector<Memory>& memories) {
  std::vector<Point2d> points;
  std::vector<std::vector<Entry>*> into;
  for (Memory& m : memories) m.collect(points, into);
  if (points.empty()) {
    for (Memory& m : memories) m.keep();
    return false;
  }
  std::vector<double> values(points.size());
  batch_(points, values);
  ++batches_;
  evaluations_ += static_cast<long long>(points.size());
  // The lists were filled in the order of `points`.
  size_t next = 0;
  for (size_t k = 0; k < into.size(); k = next) {
    std::vector<Entry>& list = *into[k];
    for (Entry& e : list) e.value = values[next++];
  }
  for (Memory& m : memories) m.keep();
  return true;
}

void BatchedDensity::run(const std::function<void(const DensityFn& f)>& compute) {
  std::vector<Memory> memory(1);
  const DensityFn f = Lookup(memory[0]);
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
      task(i, Lookup(m));
      if (m.complete()) {
        done[i] = 1;
        m.forget();  // its result is final
      }
    });
  } while (evaluateMissing(memories));
}

}  // namespace verity::chi2
