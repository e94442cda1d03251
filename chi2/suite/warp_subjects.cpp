#include "chi2/suite/warp_subjects.h"

#include <fmt/format.h>
#include <verity/chi2/warp_adapter.h>
#include <verity/chi2/warp_subject.h>

#include "sampling/warp.h"

namespace verity::chi2 {

namespace {

// Verity's warps through the same front end as other renderers' (warp_adapter.h): the
// uniforms convert to Point2f, and the points are read back in double precision.
WarpModel warpModel(WarpKind kind, float parameter) {
  using namespace warp;
  switch (kind) {
    case WarpKind::DiskPolar:
      return diskWarp<Point2f>([](const Point2f& u) { return squareToUniformDiskPolar(u); },
                               squareToUniformDiskPdf);
    case WarpKind::DiskConcentric:
      return diskWarp<Point2f>([](const Point2f& u) { return squareToUniformDiskConcentric(u); },
                               squareToUniformDiskPdf);
    case WarpKind::UniformSphere:
      return sphereWarp<Vector3f>([](const Point2f& u) { return squareToUniformSphere(u); },
                                  squareToUniformSpherePdf);
    case WarpKind::UniformHemisphere:
      return hemisphereWarp<Vector3f>([](const Point2f& u) { return squareToUniformHemisphere(u); },
                                      squareToUniformHemispherePdf);
    case WarpKind::CosineHemisphere:
      return hemisphereWarp<Vector3f>([](const Point2f& u) { return squareToCosineHemisphere(u); },
                                      squareToCosineHemispherePdf);
    case WarpKind::SphericalCap: {
      WarpModel m = sphereWarp<Vector3f>(
          [parameter](const Point2f& u) { return squareToUniformSphericalCap(u, parameter); },
          [parameter](const Vector3f& v) { return squareToUniformSphericalCapPdf(v, parameter); });
      // The cap's rim, at every azimuth.
      m.breakpointsY = [parameter](double) { return std::vector<double>{parameter}; };
      return m;
    }
    case WarpKind::Triangle:
      return triangleWarp<Point2f>([](const Point2f& u) { return squareToUniformTriangle(u); },
                                   squareToUniformTrianglePdf);
    case WarpKind::SquareIdentity:
      break;
  }
  return squareWarp<Point2f>([](const Point2f& u) { return u; },
                             [](const Point2f&) { return 1.0; });
}

}  // namespace

std::string warpName(WarpKind kind) {
  static const char* names[] = {"disk_polar",         "disk_concentric",   "uniform_sphere",
                                "uniform_hemisphere", "cosine_hemisphere", "spherical_cap",
                                "triangle",           "square_identity"};
  return names[static_cast<int>(kind)];
}

std::unique_ptr<Subject> makeWarpSubject(WarpKind kind, float parameter, int res) {
  const std::string name = kind == WarpKind::SphericalCap
                               ? fmt::format("warp {} cos(theta_max)={}", warpName(kind), parameter)
                               : "warp " + warpName(kind);
  return std::make_unique<WarpSubject>(name, warpModel(kind, parameter), res);
}

std::unique_ptr<Subject> makeMicrofacetNormalSubject(const MicrofacetDistribution& dist,
                                                     const Vector3f& wi, int res) {
  const std::string name =
      fmt::format("microfacet normals {} alpha={} sampling={} wi=({:.4f}, {:.4f}, {:.4f})",
                  dist.type() == MicrofacetType::GGX ? "ggx" : "beckmann", dist.alpha(),
                  dist.sampling() == MicrofacetSampling::Visible ? "visible" : "normals", wi.x(),
                  wi.y(), wi.z());
  WarpModel m =
      hemisphereWarp<Vector3f>([dist, wi](const Point2f& u) { return dist.sampleNormal(wi, u); },
                               [dist, wi](const Vector3f& n) { return dist.pdfNormal(wi, n); });
  // Visible normals end where wi·m = 0, a great circle that at grazing incidence cuts a
  // sliver off the polar cells, narrower than the Kronrod nodes' spacing: split there.
  // With a = wi.x cos φ + wi.y sin φ, a·√(1 − z²) + wi.z·z = 0 gives z = −a/√(a² + wi.z²).
  const Eigen::Vector3d w = wi.cast<double>();
  m.breakpointsY = [w](double phi) {
    const double a = w.x() * std::cos(phi) + w.y() * std::sin(phi);
    return std::vector<double>{-a / std::sqrt(a * a + w.z() * w.z())};
  };
  m.breakpointCrossingsX = [w](double z) { return coneAzimuths(w, 0, z); };
  return std::make_unique<WarpSubject>(name, std::move(m), res);
}

}  // namespace verity::chi2
