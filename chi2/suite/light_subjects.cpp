#include "chi2/suite/light_subjects.h"

#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "lights/area_light.h"
#include "loader/scene_loader.h"
#include "shapes/quad.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"

namespace verity::chi2 {

namespace {

// The scene around the emitter; the camera is required by the format and never used.
SceneFile loadLightScene(const LightSetup& s) {
  namespace fs = std::filesystem;
  // One directory per process: ctest runs configurations in parallel processes.
  const fs::path dir = fs::temp_directory_path() / fmt::format("verity-chi2-{}", ::getpid());
  fs::create_directories(dir);
  if (!s.obj.empty()) std::ofstream(dir / "mesh.obj") << s.obj;
  const std::string text =
      fmt::format(R"({{"camera": {{"resolution": [4, 4]}}, "surfaces": {}}})", s.surfaces);
  // The loader reads the mesh before it returns; the folder goes either way.
  struct RemovedOnExit {
    fs::path dir;
    ~RemovedOnExit() {
      std::error_code ignored;
      fs::remove_all(dir, ignored);
    }
  } removed{dir};
  SceneFile file = loadSceneText(text, dir / "light.json");
  if (s.sampling != LightSampling::Choice && file.scene->lights().size() != 1)
    throw std::invalid_argument(s.name + ": the surfaces must hold exactly one emitter");
  if (s.sampling == LightSampling::Choice && file.scene->lights().size() < 2)
    throw std::invalid_argument(s.name + ": a choice needs several emitters");
  return file;
}

class LightSubject : public Subject {
 public:
  explicit LightSubject(const LightSetup& s)
      : setup_(s), file_(loadLightScene(s)), domain_(sphereDomain(s.resolution)) {
    for (const Light* light : file_.scene->lights()) {
      auto area = dynamic_cast<const AreaLight*>(light);
      if (!area) throw std::invalid_argument(s.name + ": the emitters must be area lights");
      collectEdges(area->shape());
    }
    light_ = dynamic_cast<const AreaLight*>(file_.scene->lights().front());
    sphere_ = dynamic_cast<const Sphere*>(&light_->shape());
    if (s.sampling == LightSampling::SphereArea && !sphere_)
      throw std::invalid_argument(s.name + ": area sampling is tested on spheres");
    if (s.sampling == LightSampling::Choice && sphere_)
      throw std::invalid_argument(s.name + ": a choice is tested among planar emitters");
    choice_ = file_.scene->lightChoice(setup_.ref);
  }

  // The light's outline seen from ref is where the density jumps; the inner quadrature
  // splits there (a triangle's tip inside a cell is otherwise missed by every node).
  std::vector<double> breakpointsY(double phi) const override {
    if (setup_.sampling == LightSampling::SphereArea) return {};
    if (sphere_) {
      const std::optional<Cone> cone = visibleCone();
      return cone ? coneCrossings(cone->axis, cone->cosAngle, phi) : std::vector<double>{};
    }
    // Each edge (directions A, B from ref) crosses the meridian's plane where m·d = 0.
    std::vector<double> zs;
    const Vector3d meridian(std::cos(phi), std::sin(phi), 0), m(-std::sin(phi), std::cos(phi), 0);
    for (const auto& [A, B] : edges_) {
      const double den = m.dot(B - A);
      if (den == 0) continue;
      const double t = -m.dot(A) / den;
      if (t < 0 || t > 1) continue;
      const Vector3d p = A + t * (B - A);
      if (p.dot(meridian) > 0) zs.push_back(p.z() / p.norm());
    }
    return zs;
  }

  // Where that outline passes height z: a cone's azimuths there, and each edge's where the
  // great circle through it (the cone of cosine 0 about A × B) meets the circle of height z
  // between A and B.
  std::vector<double> breakpointCrossingsX(double z) const override {
    if (setup_.sampling == LightSampling::SphereArea) return {};
    if (sphere_) {
      const std::optional<Cone> cone = visibleCone();
      return cone ? coneAzimuths(cone->axis, cone->cosAngle, z) : std::vector<double>{};
    }
    std::vector<double> phis;
    for (const auto& [A, B] : edges_) {
      const Vector3d m = A.cross(B);
      if (!(m.norm() > 0)) continue;
      for (double phi : coneAzimuths(m.normalized(), 0, z)) {
        const Vector3d w = sphereDirection(phi, z);
        if (A.cross(w).dot(m) >= 0 && w.cross(B).dot(m) >= 0) phis.push_back(phi);
      }
    }
    return phis;
  }

  std::vector<Point2d> peaks() const override {
    if (setup_.sampling == LightSampling::SphereArea || !sphere_) return {};
    const std::optional<Cone> cone = visibleCone();
    return cone ? coneTangentPoints(cone->axis, cone->cosAngle) : std::vector<Point2d>{};
  }

  const Domain& domain() const override { return domain_; }

  double pdf(double phi, double z) const override {
    const Vector3f d = sphereDirectionAtLastAzimuth(phi, z).cast<float>();
    if (setup_.sampling == LightSampling::SphereArea)
      // Uniform by area: per dφ d(cos θ) about the centre, pdfArea · r².
      return double(sphere_->sampleArea(Point2f(0.5f, 0.5f)).pdf) * sphere_->radius() *
             sphere_->radius();
    SurfaceInteraction si;
    if (!file_.scene->intersect(Ray(setup_.ref, d), si) || !si.light) return 0;
    // Points whose front side faces away emit nothing: sampleLi declines them.
    if (!(si.ng.dot(-d) > 0)) return 0;
    if (setup_.sampling == LightSampling::Choice)
      return double{choice_.pmf(si.light)} * si.light->pdfLi(setup_.ref, si.p, si.ng);
    return si.light == light_ ? light_->pdfLi(setup_.ref, si.p, si.ng) : 0;
  }

  std::optional<Point2d> sample(pcg32& rng, Audit& audit) const override {
    const float a = uniform01(rng);
    const Point2f u(a, uniform01(rng));
    if (setup_.sampling == LightSampling::SphereArea) {
      const ShapeSample s = sphere_->sampleArea(u);
      return checked((s.p - sphere_->center()).normalized(), s.pdf, audit);
    }
    const AreaLight* light = light_;
    float pmf = 1;
    if (setup_.sampling == LightSampling::Choice) {
      light = static_cast<const AreaLight*>(choice_.sample(uniform01(rng), &pmf));
      if (!light) return std::nullopt;
      const float reported = choice_.pmf(light);
      if (pmf != reported)
        audit.record(Defect::SamplePdf,
                     fmt::format("LightChoice::sample's pmf {} != pmf() {}", pmf, reported));
    }
    const auto ls = light->sampleLi(setup_.ref, u);
    if (!ls) return std::nullopt;
    if (!ls->radiance.allFinite() || (ls->radiance.array() < 0).any())
      audit.record(Defect::NonFinite,
                   fmt::format("sampleLi radiance ({}, {}, {})", ls->radiance.x(), ls->radiance.y(),
                               ls->radiance.z()));
    // The returned density must be the one pdfLi() reports for the chosen point.
    const float pdf = light->pdfLi(setup_.ref, ls->p, ls->n);
    if (!relativelyClose(ls->pdf, pdf, kWeightTolerance))
      audit.record(Defect::SamplePdf, fmt::format("sampleLi pdf {} != pdfLi {} at p ({}, {}, {})",
                                                  ls->pdf, pdf, ls->p.x(), ls->p.y(), ls->p.z()));
    return checked(ls->wi, pmf * ls->pdf, audit);
  }

  // The outline's corners: an edge along a meridian is a jump in φ, a corner a kink.
  std::vector<double> breakpointsX() const override {
    std::vector<double> xs;
    for (const auto& [a, b] : edges_) {
      const double phi = std::atan2(a.y(), a.x());
      xs.push_back(phi < 0 ? phi + 2 * kPi : phi);
    }
    return xs;
  }

  std::string describe() const override {
    return fmt::format("light {} ({}) from ({}, {}, {}): {}", setup_.name,
                       setup_.sampling == LightSampling::SphereArea ? "sphere area"
                       : setup_.sampling == LightSampling::Choice   ? "choice of a light"
                                                                    : "solid angle",
                       setup_.ref.x(), setup_.ref.y(), setup_.ref.z(), setup_.surfaces);
  }

 private:
  struct Cone {
    Vector3d axis;
    double cosAngle;
  };
  // The sphere as seen from ref: d·c = cos θmax about the direction c to the centre.
  std::optional<Cone> visibleCone() const {
    const Vector3d toCentre = (sphere_->center() - setup_.ref).cast<double>();
    const double dist = toCentre.norm(), r = sphere_->radius();
    if (dist <= r) return std::nullopt;
    return Cone{toCentre / dist, std::sqrt(1 - (r / dist) * (r / dist))};
  }

  static std::optional<Point2d> checked(const Vector3f& d, float pdf, Audit& audit) {
    if (!d.allFinite() || !std::isfinite(pdf) || !(pdf > 0)) {
      audit.record(Defect::NonFinite,
                   fmt::format("direction ({}, {}, {}) with pdf {}", d.x(), d.y(), d.z(), pdf));
      return std::nullopt;
    }
    return sphereCoords(d.cast<double>());
  }

  void collectEdges(const Shape& shape) {
    std::vector<std::vector<Point3f>> polygons;
    if (auto quad = dynamic_cast<const Quad*>(&shape)) {
      const auto c = quad->corners();
      polygons.push_back({c.begin(), c.end()});
    } else if (auto mesh = dynamic_cast<const TriangleMesh*>(&shape)) {
      const MeshData& d = mesh->data();
      for (size_t i = 0; i + 2 < d.indices.size(); i += 3)
        polygons.push_back({d.positions[d.indices[i]], d.positions[d.indices[i + 1]],
                            d.positions[d.indices[i + 2]]});
    }
    for (const auto& poly : polygons)
      for (size_t i = 0; i < poly.size(); ++i)
        edges_.emplace_back((poly[i] - setup_.ref).cast<double>(),
                            (poly[(i + 1) % poly.size()] - setup_.ref).cast<double>());
  }

  LightSetup setup_;
  std::vector<std::pair<Vector3d, Vector3d>> edges_;  // outline edges, relative to ref
  SceneFile file_;
  Domain domain_;
  const AreaLight* light_ = nullptr;
  const Sphere* sphere_ = nullptr;
  LightChoice choice_;  // next-event estimation's choice at ref, made once
};

}  // namespace

std::unique_ptr<Subject> makeLightSubject(const LightSetup& setup) {
  return std::make_unique<LightSubject>(setup);
}

}  // namespace verity::chi2
