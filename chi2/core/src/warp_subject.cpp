#include <fmt/format.h>
#include <tbb/parallel_for.h>
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

Vector3d WarpSubject::point(double x, double y) const {
  return isDirectional(model_.domain) ? sphereDirectionAtLastAzimuth(x, y) : Vector3d(x, y, 0);
}

double WarpSubject::pdf(double x, double y) const {
  return model_.pdf(point(x, y));
}

void WarpSubject::pdfBatch(const std::vector<Point2d>& points, std::vector<double>& values) const {
  std::vector<Vector3d> p(points.size());
  tbb::parallel_for(size_t(0), points.size(),
                    [&](size_t k) { p[k] = point(points[k].x(), points[k].y()); });
  model_.pdfBatch(p, values);
}

namespace {

Uniform2 drawUniforms(pcg32& rng) {
  Uniform2 u;
  u.x = uniform01(rng);
  u.y = uniform01(rng);
  return u;
}

}  // namespace

std::optional<Point2d> WarpSubject::sample(pcg32& rng, Audit& audit) const {
  const Uniform2 u = drawUniforms(rng);
  return audited(u, model_.sample(u), audit);
}

void WarpSubject::sampleBatch(pcg32& rng, std::vector<std::optional<Point2d>>& out,
                              Audit& audit) const {
  if (!model_.sampleBatch) return Subject::sampleBatch(rng, out, audit);
  std::vector<Uniform2> us(out.size());
  for (Uniform2& u : us) u = drawUniforms(rng);
  std::vector<std::optional<Vector3d>> drawn(out.size());
  model_.sampleBatch(us, drawn);
  for (size_t k = 0; k < out.size(); ++k) out[k] = audited(us[k], drawn[k], audit);
}

std::optional<Point2d> WarpSubject::audited(const Uniform2& u, const std::optional<Vector3d>& p,
                                            Audit& audit) const {
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

std::vector<double> WarpSubject::breakpointCrossingsX(double y) const {
  return model_.breakpointCrossingsX ? model_.breakpointCrossingsX(y) : std::vector<double>{};
}

}  // namespace verity::chi2
