// The quadrature's computations (quadrature.cpp), for the partition's (partition.cpp) to await:
// the same integrals as integrateCell, and tabulations, given a Density (density.h). The
// bounds and options are taken by value: a computation may start after its caller's temporaries.
#pragma once

#include <verity/chi2/quadrature.h>

#include <array>
#include <functional>
#include <vector>

#include "density.h"

namespace verity::chi2 {

Task<CellIntegral> cellIntegral(Density& f, const DensityFeatures& features, const Domain& domain,
                                int cell, QuadratureOptions options);

// Tabulations, for the partition (partition.cpp) to invert: a nested integral's pieces as its
// refinement left them, with the density at each rule's nodes.
inline constexpr size_t kRuleNodes = 15;
// A piece [a, b] of an adaptive integral: its Kronrod rule's value and the integrand at the
// rule's nodes, in the order of ruleWeights.
struct QuadratureLeaf {
  double a = 0, b = 0, value = 0;
  std::array<double, kRuleNodes> at{};
};
// The inner integral over y at x, as the quadrature computes it: its value, error estimate and
// leaves in order (none where the support is empty at x).
struct Profile {
  double x = 0, value = 0, error = 0;
  std::vector<QuadratureLeaf> leaves;
};
// An outer leaf in x (its values: the inner integrals at its nodes) with the profile at each node.
struct OuterLeaf {
  QuadratureLeaf leaf;
  std::array<Profile, kRuleNodes> profiles;
};
// ∫∫ f over a rectangle, as integrateRectangle refines it, as its outer leaves. Then leaves
// holding more than xShare of the whole (of their profile: yShare) are bisected until they
// hold no more, so that a distribution inverted inside them is resolved (0: not at all).
Task<std::vector<OuterLeaf>> tabulateRectangle(Density& f, const DensityFeatures& features,
                                               const Domain& domain, CellBounds rectangle,
                                               QuadratureOptions options, double xShare,
                                               double yShare);
// The same with the tolerances that options(mass) gives for the rectangle's mass, estimated
// first by one rule on each piece of the tabulation's first level (options(0) to depth 0),
// whose evaluations the tabulation then reuses.
Task<std::vector<OuterLeaf>> tabulateRectangleToItsMass(
    Density& f, const DensityFeatures& features, const Domain& domain, CellBounds rectangle,
    std::function<QuadratureOptions(double mass)> options, double xShare, double yShare);
// The profile along y at x, as the nested integral over `rectangle` would compute it there: so
// that a tabulation's ends (x = rectangle.x0, x1), which its rule's nodes never reach, can be
// seen.
Task<Profile> profileAlongY(Density& f, const DensityFeatures& features, const Domain& domain,
                            CellBounds rectangle, QuadratureOptions options, double x);
// The rule's nodes' weights on [a, b], in the order of QuadratureLeaf::at.
std::array<double, kRuleNodes> ruleWeights(double a, double b);
// The integral from a to a + (b − a)·j/steps, j = 1 … steps, of the polynomial interpolating
// the leaf's values at the rule's nodes; the rule is interpolatory, so the last is the leaf's
// value (up to rounding). steps divides kLeafSteps.
inline constexpr int kLeafSteps = 32;
std::vector<double> leafCumulative(const QuadratureLeaf& leaf, int steps);

}  // namespace verity::chi2
