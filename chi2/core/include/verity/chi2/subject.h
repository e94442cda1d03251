// What a sampling test examines: a sampler and the density it claims, on a domain. Warps,
// BSDFs and light samplers (chi2/suite) are adapted to this one interface.
#pragma once

#include <verity/chi2/audit.h>
#include <verity/chi2/domain.h>

#include <optional>
#include <pcg_random.hpp>
#include <string>
#include <vector>

namespace verity::chi2 {

// The samples drawn from one random stream (one PCG32 sequence, numbered from 0): a check's
// samples are drawn block by block, so that they do not depend on the number of threads.
inline constexpr long long kSamplesPerStream = 1 << 16;

class Subject {
 public:
  virtual ~Subject() = default;
  virtual const Domain& domain() const = 0;
  // Density per dx dy of the domain at (x, y); thread-safe. Non-finite or negative values
  // are recorded by the caller.
  virtual double pdf(double x, double y) const = 0;
  // One sample in domain coordinates, or nothing when the sampler declines (an invalid
  // sample). Per-sample defects go to `audit`; thread-safe with one rng/audit per thread.
  virtual std::optional<Point2d> sample(pcg32& rng, Audit& audit) const = 0;
  // Batched forms, for a sampler or density whose cost is in the call (SIMD or GPU code, a
  // NumPy function): runSamplingTest draws each chunk of samples with one sampleBatch, which
  // must draw from rng as n calls of sample() would (the default is those calls), and, where
  // batchedPdf(), integrates the density through pdfBatch (DensityBatchFn, quadrature.h), with the
  // same cell probabilities as pdf() point by point.
  virtual void sampleBatch(pcg32& rng, std::vector<std::optional<Point2d>>& out,
                           Audit& audit) const;
  virtual bool batchedPdf() const { return false; }
  // values[k] = pdf(points[k]); the default calls pdf().
  virtual void pdfBatch(const std::vector<Point2d>& points, std::vector<double>& values) const;
  // Where the density may jump inside the domain along y at abscissa x (e.g. a shading
  // horizon that crosses cells): the inner quadrature splits there instead of refining a
  // discontinuity to its maximum depth.
  virtual std::vector<double> breakpointsY(double x) const { return {}; }
  // The abscissae where those jumps pass through height y (a cone's crossings of the
  // meridians meet a circle of latitude): a cell's outer quadrature splits there. Where a
  // jump dips just into a cell, the density in the cell is a sliver next to that edge,
  // narrower than the spacing of the outer rule's nodes, which would read it as zero.
  virtual std::vector<double> breakpointCrossingsX(double y) const { return {}; }
  // Abscissae where the density jumps or kinks for every y (an edge along a meridian): the
  // outer quadrature splits there.
  virtual std::vector<double> breakpointsX() const { return {}; }
  // Points where the density may gather into a lobe far narrower than a cell (a mirror or
  // a refraction direction at tiny roughness or an index near 1): the quadrature grades its
  // cuts towards them instead of hoping that bisection finds them.
  virtual std::vector<Point2d> peaks() const { return {}; }
  // How many samples so far were delta lobes (a mirror, a refraction), which sample() counts
  // and declines: a histogram cannot test them, so a test of nothing else is not PASSED.
  virtual long long deltaSamples() const { return 0; }
  // Deterministic checks independent of sampling (e.g. eval at cell centres).
  virtual void extraChecks(Audit& audit) const {}
  virtual std::string describe() const = 0;
};

// A uniform float in [0, 1) from the generator (24 random bits).
inline float uniform01(pcg32& rng) {
  return static_cast<float>(rng() >> 8) * 0x1p-24f;
}

}  // namespace verity::chi2
