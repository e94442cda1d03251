// The two-dimensional domains on which samples are histogrammed. Each domain is a
// rectangle of parameters (x, y) split into nx × ny cells, with a support that may be a
// sub-region of the rectangle (the disk, the triangle); densities are always expressed
// with respect to dx dy, so the parameterisations are chosen to be measure-preserving.
// The cells are axis-aligned rectangles: nx strips in x, each cut into ny cells in y,
// either the uniform grid or with edges of their own (equal-probability cells, partition.h).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace verity::chi2 {

using Point2d = Eigen::Vector2d;
using Vector3d = Eigen::Vector3d;

enum class DomainKind {
  // Directions as (φ ∈ [0, 2π), cos θ ∈ [−1, 1]): dω = dφ d(cos θ) (Archimedes), so the
  // density per dφ dz equals the solid-angle density.
  Sphere,
  Square,    // [0, 1]²
  Disk,      // the unit disk in Cartesian coordinates inside [−1, 1]²
  Triangle,  // barycentric (b0, b1) with b0, b1 ≥ 0, b0 + b1 ≤ 1, inside [0, 1]²
};

// One cell's rectangle [x0, x1] × [y0, y1] (before clipping by the support).
struct CellBounds {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
};

struct Domain {
  DomainKind kind = DomainKind::Square;
  int nx = 1, ny = 1;
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  // The cells' own edges, where they are not the uniform grid's: nx + 1 strip edges from x0
  // to x1, and for strip i its ny + 1 edges from y0 to y1 at yEdges[i·(ny + 1) …]. Empty:
  // the uniform grid. Cell (i, j) is number j·nx + i either way.
  std::vector<double> xEdges, yEdges;
  // Why the cells are the uniform grid although others were asked for; empty otherwise.
  std::string gridReason;

  int cells() const { return nx * ny; }
  bool uniform() const { return xEdges.empty(); }
  // The uniform grid's cell size: the nominal size under other layouts, whose own cells
  // cell() gives.
  double cellWidth() const { return (x1 - x0) / nx; }
  double cellHeight() const { return (y1 - y0) / ny; }
  double xEdge(int i) const;
  double yEdge(int i, int j) const;  // strip i's j-th edge
  CellBounds cell(int c) const;
  // The support's extent in y at abscissa x, clipped to [lo, hi]; empty when lo ≥ hi.
  std::pair<double, double> clipY(double x, double lo, double hi) const;
  // The support's extent in y over the strip x ∈ [xa, xb] (the rectangle's where it is one).
  std::pair<double, double> supportY(double xa, double xb) const;
  bool inSupport(const Point2d& p) const;
  // The cell holding p, or −1 outside the rectangle. Cells are half-open, the last closed
  // (binary search in the edges where they are not uniform; CellLocator, cell_locator.h, finds
  // the same cell in constant expected time, for binning millions of samples).
  int cellOf(const Point2d& p) const;
  std::string name() const;
};

Domain sphereDomain(int thetaCells);  // 2·thetaCells cells in φ, thetaCells in cos θ
Domain squareDomain(int cells);
Domain diskDomain(int cells);
Domain triangleDomain(int cells);

// Sphere parameterisation and its inverse (unit vectors; the inverse normalises).
Vector3d sphereDirection(double phi, double z);
// sphereDirection(φ, z) for a pdf on the sphere (BSDFs, directional warps, lights) evaluated
// by the quadrature, whose inner integrals ask for many z at one φ: cos φ and sin φ are
// computed again only when φ changes (a tenth of a rough dielectric's test time was spent
// recomputing them). Same values; one per thread.
Vector3d sphereDirectionAtLastAzimuth(double phi, double z);
Point2d sphereCoords(const Vector3d& v);
// The cos θ values at azimuth φ where a direction meets the cone ω·axis = cosAngle (none,
// one or two; a great circle when cosAngle = 0): where a density bounded by that cone jumps.
std::vector<double> coneCrossings(const Vector3d& axis, double cosAngle, double phi);
// The azimuths φ in [0, 2π) where the circle of height cos θ = z meets that cone (none, one or
// two): where the cone's crossings of the meridians pass through height z.
std::vector<double> coneAzimuths(const Vector3d& axis, double cosAngle, double z);
// The points (φ, cos θ) where a meridian touches that cone: the ends of its range in φ (none
// when the cone holds a pole). Across them the length of the cone's chord along a meridian
// grows like √|Δφ|, a singularity of the integral over φ.
std::vector<Point2d> coneTangentPoints(const Vector3d& axis, double cosAngle);

}  // namespace verity::chi2
