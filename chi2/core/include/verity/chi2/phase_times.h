// Where a check's time went: wall-clock seconds per phase, so that a slow check says whether
// its cost is in drawing the samples, in the cells, in the quadrature or in the audit, and
// how far it lies from the floor of drawing and binning the samples alone.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <string>

namespace verity::chi2 {

enum class Phase {
  Cells,       // the equal-probability partition (partition.h); none on the grid
  Quadrature,  // the claimed pdf integrated over every cell
  Drawing,     // the samples drawn from the sampler
  Audit,       // the per-sample checks (audit.h) and the checks at cell centres
  Binning,     // the samples histogrammed in the cells
  DeltaLobes,  // the delta lobes' own draws and checks (delta_check.h)
  Statistics,  // the chi-square and pdf-integral tests and what they could have caught
  Figure,      // the figure and its data
  Count
};

// "cells", "quadrature", "drawing", "audit", "binning", "delta lobes", "statistics", "figure"
const char* phaseName(Phase phase);

class PhaseTimes {
 public:
  void add(Phase phase, double seconds) { seconds_[static_cast<int>(phase)] += seconds; }
  double operator[](Phase phase) const { return seconds_[static_cast<int>(phase)]; }
  double total() const;
  // "cells 0.41 s, quadrature 0.12 s, ...": the phases that took any time, in order.
  std::string describe() const;

 private:
  std::array<double, static_cast<int>(Phase::Count)> seconds_{};
};

// The seconds since its construction.
class PhaseClock {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// What a running check has reached, for a display on another thread (`verity chi2` shows it on
// a terminal once a check has run a few seconds): its phase and, while it draws, how many of its
// samples are drawn. Phase::Count before it starts and after it ends.
struct CheckProgress {
  std::atomic<Phase> phase{Phase::Count};
  std::atomic<long long> drawn{0}, samples{0};
  // Of a run of several checks (a family, family_check.h): the one under way, from 1, and how
  // many there are; 0 of 0 for a single check.
  std::atomic<long long> check{0}, checks{0};
};

// Adds the seconds from its construction to its destruction to `times`' phase.
class PhaseTimer {
 public:
  PhaseTimer(PhaseTimes& times, Phase phase) : times_(times), phase_(phase) {}
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;
  ~PhaseTimer() { times_.add(phase_, clock_.seconds()); }

 private:
  PhaseTimes& times_;
  Phase phase_;
  PhaseClock clock_;
};

}  // namespace verity::chi2
