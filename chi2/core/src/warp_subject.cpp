#include <fmt/format.h>
#include <verity/chi2/warp_subject.h>

#include <cmath>

namespace verity::chi2 {

namespace {

Domain domainOf(WarpDomain d, int resolution) {
  switch (d) {
    case WarpDomain::Square:
      return squareDomain(resolution);
    case WarpDomain::Disk:
      return diskDomain(resolution);
    case WarpDomain::Triangle:
      return triangleDomain(resolution);
    case WarpDomain::Hemisphere:
    case WarpDomain::Sphere:
      break;
  }
  return sphereDomain(resolution);
}

}  // namespace

bool isDirectional(WarpDomain domain) {
  return domain == WarpDomain::Hemisphere || domain == WarpDomain::Sphere;
}

WarpSubject::WarpSubject(std::string name, WarpModel model, int resolution)
    : name_(std::move(name)),
      model_(std::move(model)),
      domain_(domainOf(model_.domain, resolution)) {}

double WarpSubject::pdf(double x, double y) const {
  return model_.pdf(isDirectional(model_.domain) ? sphereDirectionAtLastAzimuth(x, y)
                                                 : Vector3d(x, y, 0));
}

std::optional<Point2d> WarpSubject::sample(pcg32& rng, Audit& audit) const {
  Uniform2 u;
  u.x = uniform01(rng);
  u.y = uniform01(rng);
  const std::optional<Vector3d> p = model_.sample(u);
  if (!p) return std::nullopt;
  if (!p->allFinite()) {
    audit.record(Defect::NonFinite, fmt::format("sampled point ({}, {}, {}) at u=({}, {})", p->x(),
                                                p->y(), p->z(), u.x, u.y));
    return std::nullopt;
  }
  if (!isDirectional(model_.domain)) return Point2d(p->x(), p->y());
  if (std::fabs(p->norm() - 1) > 1e-3) {
    audit.record(Defect::NotUnit,
                 fmt::format("sampled direction ({}, {}, {}) not a unit vector at u=({}, {})",
                             p->x(), p->y(), p->z(), u.x, u.y));
    return std::nullopt;
  }
  return sphereCoords(*p);
}

std::vector<double> WarpSubject::breakpointsY(double x) const {
  std::vector<double> breaks = model_.breakpointsY ? model_.breakpointsY(x) : std::vector<double>{};
  // A hemisphere's density ends at the horizon.
  if (model_.domain == WarpDomain::Hemisphere) breaks.push_back(0);
  return breaks;
}

}  // namespace verity::chi2
