#include "materials/phong.h"

#include "core/frame.h"
#include "materials/material_factory.h"
#include "materials/material_keys.h"
#include "materials/sample_util.h"
#include "sampling/warp.h"

namespace verity {

namespace {
// cos α between wo and the mirror direction of wi (equal to that of wi and the mirror of
// wo, hence reciprocity). The lobe is zero beyond 90° from the mirror direction, also for
// exponent 0, where cos⁰ would otherwise fill the whole sphere.
float cosAlpha(const Vector3f& wi, const Vector3f& wo) {
  return std::min(Vector3f(-wi.x(), -wi.y(), wi.z()).dot(wo), 1.0f);
}
}  // namespace

Color3 Phong::eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
                   TransportMode) const {
  const float cosA = cosAlpha(wi, wo);
  if (wi.z() <= 0 || wo.z() <= 0 || !(cosA > 0)) return Color3::Zero();
  const float lobe = (exponent_ + 2.0f) * kInv2Pi * std::pow(cosA, exponent_);
  return sanitize(albedo_.eval(q) * lobe);
}

float Phong::pdf(const TextureQuery&, const Vector3f& wi, const Vector3f& wo) const {
  const float cosA = cosAlpha(wi, wo);
  if (wi.z() <= 0 || wo.z() <= 0 || !(cosA > 0)) return 0;
  return sanitize((exponent_ + 1.0f) * kInv2Pi * std::pow(cosA, exponent_));
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
