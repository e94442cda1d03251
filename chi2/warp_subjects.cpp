#include "chi2/warp_subjects.h"

#include <fmt/format.h>

#include <functional>

#include "sampling/warp.h"

namespace verity::chi2 {

namespace {

using SampleFn = std::function<std::optional<Point2d>(pcg32&, Audit&)>;

class FunctionSubject : public Subject {
 public:
  FunctionSubject(std::string name, Domain domain, SampleFn sample,
                  std::function<double(double, double)> pdf, std::vector<double> breaks = {})
      : name_(std::move(name)),
        domain_(domain),
        sample_(std::move(sample)),
        pdf_(std::move(pdf)),
        breaks_(std::move(breaks)) {}
  std::vector<double> breakpointsY(double x) const override {
    return breakFn_ ? breakFn_(x) : breaks_;
  }
  void setBreakpoints(std::function<std::vector<double>(double)> f) { breakFn_ = std::move(f); }
  const Domain& domain() const override { return domain_; }
  double pdf(double x, double y) const override { return pdf_(x, y); }
  std::optional<Point2d> sample(pcg32& rng, Audit& audit) const override {
    return sample_(rng, audit);
  }
  std::string describe() const override { return name_; }

 private:
  std::string name_;
  Domain domain_;
  SampleFn sample_;
  std::function<double(double, double)> pdf_;
  std::vector<double> breaks_;  // constant in x (the spherical cap's edge)
  std::function<std::vector<double>(double)> breakFn_;
};

Point2f draw2(pcg32& rng) {
  const float a = uniform01(rng);
  return {a, uniform01(rng)};
}

// A sampled direction as sphere coordinates, with its finiteness audited.
std::optional<Point2d> directionSample(const Vector3f& v, Audit& audit) {
  if (!v.allFinite()) {
    audit.record(Defect::NonFinite,
                 fmt::format("sampled direction ({}, {}, {})", v.x(), v.y(), v.z()));
    return std::nullopt;
  }
  return sphereCoords(v.cast<double>());
}

std::optional<Point2d> pointSample(const Point2f& p, Audit& audit) {
  if (!p.allFinite()) {
    audit.record(Defect::NonFinite, fmt::format("sampled point ({}, {})", p.x(), p.y()));
    return std::nullopt;
  }
  return p.cast<double>();
}

Vector3f toDirection(double phi, double z) {
  return sphereDirection(phi, z).cast<float>();
}

}  // namespace

std::string warpName(WarpKind kind) {
  static const char* names[] = {"disk_polar",         "disk_concentric",   "uniform_sphere",
                                "uniform_hemisphere", "cosine_hemisphere", "spherical_cap",
                                "triangle",           "square_identity"};
  return names[static_cast<int>(kind)];
}

std::unique_ptr<Subject> makeWarpSubject(WarpKind kind, float parameter, int res) {
  using namespace warp;
  const std::string name = kind == WarpKind::SphericalCap
                               ? fmt::format("warp {} cos(theta_max)={}", warpName(kind), parameter)
                               : "warp " + warpName(kind);
  switch (kind) {
    case WarpKind::DiskPolar:
    case WarpKind::DiskConcentric: {
      const bool polar = kind == WarpKind::DiskPolar;
      return std::make_unique<FunctionSubject>(
          name, diskDomain(res),
          [polar](pcg32& rng, Audit& a) {
            const Point2f u = draw2(rng);
            return pointSample(
                polar ? squareToUniformDiskPolar(u) : squareToUniformDiskConcentric(u), a);
          },
          [](double x, double y) { return squareToUniformDiskPdf(Point2f(float(x), float(y))); });
    }
    case WarpKind::UniformSphere:
      return std::make_unique<FunctionSubject>(
          name, sphereDomain(res),
          [](pcg32& rng, Audit& a) {
            return directionSample(squareToUniformSphere(draw2(rng)), a);
          },
          [](double phi, double z) { return squareToUniformSpherePdf(toDirection(phi, z)); });
    case WarpKind::UniformHemisphere:
      return std::make_unique<FunctionSubject>(
          name, sphereDomain(res),
          [](pcg32& rng, Audit& a) {
            return directionSample(squareToUniformHemisphere(draw2(rng)), a);
          },
          [](double phi, double z) { return squareToUniformHemispherePdf(toDirection(phi, z)); });
    case WarpKind::CosineHemisphere:
      return std::make_unique<FunctionSubject>(
          name, sphereDomain(res),
          [](pcg32& rng, Audit& a) {
            return directionSample(squareToCosineHemisphere(draw2(rng)), a);
          },
          [](double phi, double z) { return squareToCosineHemispherePdf(toDirection(phi, z)); });
    case WarpKind::SphericalCap:
      return std::make_unique<FunctionSubject>(
          name, sphereDomain(res),
          [parameter](pcg32& rng, Audit& a) {
            return directionSample(squareToUniformSphericalCap(draw2(rng), parameter), a);
          },
          [parameter](double phi, double z) {
            return squareToUniformSphericalCapPdf(toDirection(phi, z), parameter);
          },
          std::vector<double>{parameter});
    case WarpKind::Triangle:
      return std::make_unique<FunctionSubject>(
          name, triangleDomain(res),
          [](pcg32& rng, Audit& a) { return pointSample(squareToUniformTriangle(draw2(rng)), a); },
          [](double x, double y) {
            return squareToUniformTrianglePdf(Point2f(float(x), float(y)));
          });
    case WarpKind::SquareIdentity:
      return std::make_unique<FunctionSubject>(
          name, squareDomain(res), [](pcg32& rng, Audit& a) { return pointSample(draw2(rng), a); },
          [](double, double) { return 1.0; });
  }
  return nullptr;
}

std::unique_ptr<Subject> makeMicrofacetNormalSubject(const MicrofacetDistribution& dist,
                                                     const Vector3f& wi, int res) {
  const std::string name =
      fmt::format("microfacet normals {} alpha={} sampling={} wi=({:.4f}, {:.4f}, {:.4f})",
                  dist.type() == MicrofacetType::GGX ? "ggx" : "beckmann", dist.alpha(),
                  dist.sampling() == MicrofacetSampling::Visible ? "visible" : "normals", wi.x(),
                  wi.y(), wi.z());
  auto subject = std::make_unique<FunctionSubject>(
      name, sphereDomain(res),
      [dist, wi](pcg32& rng, Audit& a) -> std::optional<Point2d> {
        const Vector3f m = dist.sampleNormal(wi, draw2(rng));
        return directionSample(m, a);
      },
      [dist, wi](double phi, double z) { return double(dist.pdfNormal(wi, toDirection(phi, z))); });
  // Visible normals end where wi·m = 0, a great circle that at grazing incidence cuts a
  // sliver off the polar cells, narrower than the Kronrod nodes' spacing: split there.
  // With a = wi.x cos φ + wi.y sin φ, a·√(1 − z²) + wi.z·z = 0 gives z = −a/√(a² + wi.z²).
  const Eigen::Vector3d w = wi.cast<double>();
  subject->setBreakpoints([w](double phi) {
    const double a = w.x() * std::cos(phi) + w.y() * std::sin(phi);
    return std::vector<double>{-a / std::sqrt(a * a + w.z() * w.z()), 0.0};
  });
  return subject;
}

}  // namespace verity::chi2
