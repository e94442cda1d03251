#include "materials/phong.h"

#include <numbers>

#include "core/frame.h"
#include "materials/material_factory.h"
#include "materials/material_keys.h"
#include "materials/sample_util.h"
#include "sampling/warp.h"

namespace verity {

namespace {
// cos α between wo and the mirror direction of wi (equal to that of wi and the mirror of
// wo, hence reciprocity). The lobe is zero beyond 90° from the mirror direction, also for
// exponent 0, where cos⁰ would otherwise fill the whole sphere. In double precision
// (unitDouble, sample_util.h): at exponent 1e6 the lobe is 1e-3 rad wide, 1 − cos α about
// 5e-7, and single precision's steps of 6e-8 in cos α, each changing cos^1e6 α by 6%, gave
// pdf integrals of 1.0019 at 0° and 1.0689 at 45°.
double cosAlpha(const Vector3f& wi, const Vector3f& wo) {
  const Eigen::Vector3d i = unitDouble(wi);
  return std::min(Eigen::Vector3d(-i.x(), -i.y(), i.z()).dot(unitDouble(wo)), 1.0);
}

// The normalised lobe (n + c)/(2π) cos^n α, c = 2 for eval() (energy conserving at normal
// incidence) and c = 1 for pdf() (a density over the hemisphere about the mirror direction).
float lobe(float exponent, double c, double cosA) {
  return float((exponent + c) / (2 * std::numbers::pi) * std::pow(cosA, double(exponent)));
}
}  // namespace

Color3 Phong::eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
                   TransportMode) const {
  if (wi.z() <= 0 || wo.z() <= 0) return Color3::Zero();
  const double cosA = cosAlpha(wi, wo);
  if (!(cosA > 0)) return Color3::Zero();
  return sanitize(albedo_.eval(q) * lobe(exponent_, 2, cosA));
}

float Phong::pdf(const TextureQuery&, const Vector3f& wi, const Vector3f& wo) const {
  if (wi.z() <= 0 || wo.z() <= 0) return 0;
  const double cosA = cosAlpha(wi, wo);
  if (!(cosA > 0)) return 0;
  return sanitize(lobe(exponent_, 1, cosA));
}

std::optional<BsdfSample> Phong::sample(const TextureQuery& q, const Vector3f& wi, float,
                                        const Point2f& u, TransportMode mode) const {
  if (wi.z() <= 0) return std::nullopt;
  const Frame lobeFrame(Vector3f(-wi.x(), -wi.y(), wi.z()).normalized());
  const Vector3f wo = lobeFrame.toWorld(warp::squareToPowerCosineLobe(u, exponent_)).normalized();
  if (wo.z() <= 0) return std::nullopt;  // the lobe dips below the horizon
  return makeSample(wo, eval(q, wi, wo, mode), pdf(q, wi, wo), kReflection | kGlossy);
}

MaterialType phongType() {
  return {"phong",
          {},
          "normalised modified Phong lobe",
          declarations(
              kAlbedo.described("the reflected fraction of light, at most"),
              kExponent.described("the lobe's sharpness: cos^exponent about the mirror direction")),
          [](MaterialFactory& f, const JsonNode& node) -> std::shared_ptr<const Material> {
            TexturedColor albedo = f.parseAlbedo(node);
            const float exponent = node.get(kExponent);
            return std::make_shared<Phong>(std::move(albedo), exponent);
          }};
}

}  // namespace verity
