#include <verity/chi2/domain.h>

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

int Domain::cellOf(const Point2d& p) const {
  if (!(p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1)) return -1;
  const int i = std::min(nx - 1, static_cast<int>((p.x() - x0) / (x1 - x0) * nx));
  const int j = std::min(ny - 1, static_cast<int>((p.y() - y0) / (y1 - y0) * ny));
  return j * nx + i;
}

std::string Domain::name() const {
  const char* names[] = {"sphere (phi, cos theta)", "square", "disk", "triangle (barycentric)"};
  return std::string(names[static_cast<int>(kind)]) + " " + std::to_string(nx) + "x" +
         std::to_string(ny);
}

Domain sphereDomain(int thetaCells) {
  return {DomainKind::Sphere, 2 * thetaCells, thetaCells, 0, 2 * std::numbers::pi, -1, 1};
}
Domain squareDomain(int cells) {
  return {DomainKind::Square, cells, cells, 0, 1, 0, 1};
}
Domain diskDomain(int cells) {
  return {DomainKind::Disk, cells, cells, -1, 1, -1, 1};
}
Domain triangleDomain(int cells) {
  return {DomainKind::Triangle, cells, cells, 0, 1, 0, 1};
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
