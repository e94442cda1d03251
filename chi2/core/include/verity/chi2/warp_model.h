// A sampling routine for a point on one of the usual domains, as the checks see it: two
// functions in double precision. warp_adapter.h builds one from callables in the caller's
// own types.
//
// Points and densities, per domain:
//   Square      (x, y) in [0, 1]², density per unit area
//   Disk        (x, y) in the unit disk, density per unit area
//   Triangle    barycentric (b0, b1), b0, b1 ≥ 0, b0 + b1 ≤ 1, density per unit (b0, b1) area
//               (2 for a uniform sampler)
//   Hemisphere  a unit vector with z ≥ 0, density per unit solid angle
//   Sphere      a unit vector, density per unit solid angle
// Planar points are held as (x, y, 0).
#pragma once

#include <verity/chi2/uniforms.h>

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <vector>

namespace verity::chi2 {

enum class WarpDomain { Square, Disk, Triangle, Hemisphere, Sphere };

struct WarpModel {
  WarpDomain domain = WarpDomain::Square;
  // Nothing when the routine declines (a rejection sampler's miss): the point weighs zero,
  // and ∫pdf must equal the probability of a valid point.
  std::function<std::optional<Eigen::Vector3d>(const Uniform2&)> sample;
  std::function<double(const Eigen::Vector3d&)> pdf;
  // Optional: where the density jumps along the domain's y at abscissa x (on the sphere,
  // the values of cos θ at azimuth φ, e.g. the rim of a spherical cap), so that the
  // quadrature splits there rather than refining a discontinuity.
  std::function<std::vector<double>(double x)> breakpointsY;
  // Optional, with breakpointsY: the abscissae where those jumps pass through height y
  // (Subject::breakpointCrossingsX), so that a cell which a jump only dips into is split there.
  std::function<std::vector<double>(double y)> breakpointCrossingsX;
  // Optional batched forms, one call for many points (SIMD or GPU code, NumPy): out[k] =
  // sample(u[k]) and values[k] = pdf(points[k]). Where set, the check draws each chunk of
  // samples, or integrates the density a refinement level at a time (DensityBatchFn, quadrature.h),
  // through them.
  std::function<void(const std::vector<Uniform2>& u,
                     std::vector<std::optional<Eigen::Vector3d>>& out)>
      sampleBatch;
  std::function<void(const std::vector<Eigen::Vector3d>& points, std::vector<double>& values)>
      pdfBatch;
};

bool isDirectional(WarpDomain domain);

}  // namespace verity::chi2
