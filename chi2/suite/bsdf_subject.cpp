#include "chi2/suite/bsdf_subject.h"

#include <fmt/format.h>

#include <numbers>

namespace verity::chi2 {

namespace {

std::string str(const Vector3f& v) {
  return fmt::format("({:.7g}, {:.7g}, {:.7g})", v.x(), v.y(), v.z());
}

Vector3f single(const Vector3d& v) {
  return v.cast<float>();
}

// The local incident direction as the renderer computes it, in single precision.
BsdfTestSetup testSetup(const BsdfSetup& s) {
  const Frame frame(s.normal.normalized());
  BsdfTestSetup t;
  t.name = s.name;
  t.wi = frame.toLocal(s.wi).normalized().cast<double>();
  t.frame = {frame.s.cast<double>(), frame.t.cast<double>(), frame.n.cast<double>()};
  t.resolution = s.resolution;
  t.checkReciprocity = s.checkReciprocity;
  return t;
}

}  // namespace

Vector3f incidentDirection(double degrees, bool inside) {
  const double t = degrees * std::numbers::pi / 180;
  return Vector3f(float(std::sin(t)), 0.0f, float(inside ? -std::cos(t) : std::cos(t)));
}

BsdfModel materialModel(std::shared_ptr<const Material> material) {
  // The default query: the suite's materials are untextured.
  static const TextureQuery query;
  BsdfModel m;
  m.sample = [material](const Vector3d& wi,
                        const BsdfUniforms& u) -> std::optional<DirectionSample> {
    const std::optional<BsdfSample> s =
        material->sample(query, single(wi), float(u.lobe), Point2f(float(u.xy.x), float(u.xy.y)),
                         TransportMode::Radiance);
    if (!s) return std::nullopt;
    return DirectionSample{s->wo.cast<double>(), s->weight.cast<double>(), s->pdf, s->isDelta()};
  };
  // The return type is spelled out: a deduced one would be Eigen's cast expression over the
  // temporary colour that eval() returns, read after that temporary is gone.
  m.eval = [material](const Vector3d& wi, const Vector3d& wo) -> Eigen::Array3d {
    return material->eval(query, single(wi), single(wo), TransportMode::Radiance).cast<double>();
  };
  m.evalAdjoint = [material](const Vector3d& wi, const Vector3d& wo) -> Eigen::Array3d {
    return material->eval(query, single(wi), single(wo), TransportMode::Importance).cast<double>();
  };
  m.pdf = [material](const Vector3d& wi, const Vector3d& wo) {
    return double(material->pdf(query, single(wi), single(wo)));
  };
  m.interiorIndex = material->interiorIndex();
  return m;
}

BsdfSubject::BsdfSubject(const BsdfSetup& setup)
    : BsdfModelSubject(materialModel(setup.material), testSetup(setup)),
      description_(fmt::format(
          "{}\n  normal {}, world wi {}, local wi {}", setup.name, str(setup.normal), str(setup.wi),
          str(Frame(setup.normal.normalized()).toLocal(setup.wi).normalized()))) {}

}  // namespace verity::chi2
