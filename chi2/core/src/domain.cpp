#include <verity/chi2/domain.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace verity::chi2 {

std::pair<double, double> Domain::clipY(double x, double lo, double hi) const {
  switch (kind) {
    case DomainKind::Disk: {
      const double h = std::sqrt(std::max(0.0, 1 - x * x));
      return {std::max(lo, -h), std::min(hi, h)};
    }
    case DomainKind::Triangle:
      return {std::max(lo, 0.0), std::min(hi, 1 - x)};
    default:
      return {lo, hi};
  }
}

std::pair<double, double> Domain::supportY(double xa, double xb) const {
  switch (kind) {
    case DomainKind::Disk: {
      const double nearest = xa <= 0 && xb >= 0 ? 0 : std::min(xa * xa, xb * xb);
      const double h = std::sqrt(std::max(0.0, 1 - nearest));
      return {-h, h};
    }
    case DomainKind::Triangle:
      return {0.0, std::clamp(1 - xa, 0.0, 1.0)};
    default:
      return {y0, y1};
  }
}

bool Domain::inSupport(const Point2d& p) const {
  if (!(p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1)) return false;
  switch (kind) {
    case DomainKind::Disk:
      return p.squaredNorm() <= 1;
    case DomainKind::Triangle:
      return p.x() + p.y() <= 1;
    default:
      return true;
  }
}

double Domain::xEdge(int i) const {
  if (!uniform()) return xEdges[i];
  return i == nx ? x1 : x0 + (x1 - x0) * i / nx;
}

double Domain::yEdge(int i, int j) const {
  if (!uniform()) return yEdges[i * (ny + 1) + j];
  return j == ny ? y1 : y0 + (y1 - y0) * j / ny;
}

CellBounds Domain::cell(int c) const {
  const int i = c % nx, j = c / nx;
  return {xEdge(i), xEdge(i + 1), yEdge(i, j), yEdge(i, j + 1)};
}

namespace {
// The piece of [edges[0], edges[n]] holding v: edges[k] ≤ v < edges[k + 1], the last closed.
int pieceOf(std::vector<double>::const_iterator first, int n, double v) {
  const int k = static_cast<int>(std::upper_bound(first, first + n + 1, v) - first) - 1;
  return std::clamp(k, 0, n - 1);
}
}  // namespace

int Domain::cellOf(const Point2d& p) const {
  if (!(p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1)) return -1;
  if (!uniform()) {
    const int i = pieceOf(xEdges.begin(), nx, p.x());
    return pieceOf(yEdges.begin() + i * (ny + 1), ny, p.y()) * nx + i;
  }
  const int i = std::min(nx - 1, static_cast<int>((p.x() - x0) / (x1 - x0) * nx));
  const int j = std::min(ny - 1, static_cast<int>((p.y() - y0) / (y1 - y0) * ny));
  return j * nx + i;
}

std::string Domain::name() const {
  const char* names[] = {"sphere (phi, cos theta)", "square", "disk", "triangle (barycentric)"};
  std::string s = std::string(names[static_cast<int>(kind)]) + " " + std::to_string(nx) + "x" +
                  std::to_string(ny);
  if (!uniform()) return s + " equal-probability cells";
  if (!gridReason.empty()) return s + " grid (" + gridReason + ")";
  return s;
}

namespace {
Domain grid(DomainKind kind, int nx, int ny, double x0, double x1, double y0, double y1) {
  Domain d;
  d.kind = kind;
  d.nx = nx;
  d.ny = ny;
  d.x0 = x0;
  d.x1 = x1;
  d.y0 = y0;
  d.y1 = y1;
  return d;
}
}  // namespace

Domain sphereDomain(int thetaCells) {
  return grid(DomainKind::Sphere, 2 * thetaCells, thetaCells, 0, 2 * std::numbers::pi, -1, 1);
}
Domain squareDomain(int cells) {
  return grid(DomainKind::Square, cells, cells, 0, 1, 0, 1);
}
Domain diskDomain(int cells) {
  return grid(DomainKind::Disk, cells, cells, -1, 1, -1, 1);
}
Domain triangleDomain(int cells) {
  return grid(DomainKind::Triangle, cells, cells, 0, 1, 0, 1);
}

namespace {
Vector3d sphereDirection(double cosPhi, double sinPhi, double z) {
  const double r = std::sqrt(std::max(0.0, 1 - z * z));
  return {r * cosPhi, r * sinPhi, z};
}
}  // namespace

Vector3d sphereDirection(double phi, double z) {
  return sphereDirection(std::cos(phi), std::sin(phi), z);
}

Vector3d sphereDirectionAtLastAzimuth(double phi, double z) {
  thread_local double lastPhi = 0, cosPhi = 1, sinPhi = 0;
  if (phi != lastPhi) {
    lastPhi = phi;
    cosPhi = std::cos(phi);
    sinPhi = std::sin(phi);
  }
  return sphereDirection(cosPhi, sinPhi, z);
}

namespace {
// An azimuth in (−2π, 4π) brought into [0, 2π).
double wrapAzimuth(double phi) {
  constexpr double twoPi = 2 * std::numbers::pi;
  if (phi < 0)
    phi += twoPi;
  else if (phi >= twoPi)
    phi -= twoPi;
  return phi < twoPi ? phi : 0;  // a tiny negative φ + 2π rounds to 2π
}
}  // namespace

Point2d sphereCoords(const Vector3d& v) {
  const Vector3d d = v.normalized();
  return {wrapAzimuth(std::atan2(d.y(), d.x())), std::clamp(d.z(), -1.0, 1.0)};
}

std::vector<double> coneCrossings(const Vector3d& axis, double cosAngle, double phi) {
  // On the meridian, ω = (cos β·m, sin β) with m = (cos φ, sin φ, 0): ω·axis = a cos β +
  // axis.z sin β = R cos(β − ψ), with a = m·axis, R = √(a² + axis.z²), ψ = atan2(axis.z, a).
  const double a = axis.x() * std::cos(phi) + axis.y() * std::sin(phi);
  const double R = std::hypot(a, axis.z()), psi = std::atan2(axis.z(), a);
  std::vector<double> z;
  if (!(R > 0) || std::fabs(cosAngle) > R) return z;
  const double spread = std::acos(cosAngle / R);
  for (double beta : {psi - spread, psi + spread})
    if (std::fabs(beta) <= std::numbers::pi / 2) z.push_back(std::sin(beta));
  return z;
}

std::vector<double> coneAzimuths(const Vector3d& axis, double cosAngle, double z) {
  // On the circle, ω = (s cos φ, s sin φ, z) with s = √(1 − z²): ω·axis = s·A cos(φ − φa) +
  // axis.z·z, with A = |axis.xy| and φa its azimuth.
  const double s = std::sqrt(std::max(0.0, 1 - z * z)), A = std::hypot(axis.x(), axis.y());
  if (!(s * A > 0)) return {};
  const double c = (cosAngle - axis.z() * z) / (s * A);
  if (!(std::fabs(c) <= 1)) return {};
  const double phiAxis = std::atan2(axis.y(), axis.x()), spread = std::acos(c);
  if (spread == 0) return {wrapAzimuth(phiAxis)};
  return {wrapAzimuth(phiAxis - spread), wrapAzimuth(phiAxis + spread)};
}

std::vector<Point2d> coneTangentPoints(const Vector3d& axis, double cosAngle) {
  // The meridian plane with normal m = (−sin φ, cos φ, 0) touches the cone when the axis
  // makes the cone's half-angle with it: |axis·m| = sin(half-angle). The point of contact
  // is the axis projected onto the plane, of length cos(half-angle).
  const double sinAxis = std::hypot(axis.x(), axis.y());
  const double sinHalf = std::sqrt(std::max(0.0, 1 - cosAngle * cosAngle));
  if (!(sinHalf < sinAxis) || !(cosAngle > 0)) return {};
  const double phiAxis = std::atan2(axis.y(), axis.x()), spread = std::asin(sinHalf / sinAxis);
  std::vector<Point2d> points;
  for (double phi : {phiAxis - spread, phiAxis + spread})
    points.emplace_back(wrapAzimuth(phi), std::clamp(axis.z() / cosAngle, -1.0, 1.0));
  return points;
}

}  // namespace verity::chi2
