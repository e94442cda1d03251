#include "materials/blinn_phong.h"

#include "materials/fresnel.h"
#include "materials/material_factory.h"
#include "materials/material_keys.h"
#include "materials/sample_util.h"
#include "sampling/warp.h"

namespace verity {

Color3 BlinnPhong::eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
                        TransportMode) const {
  if (wi.z() <= 0 || wo.z() <= 0) return Color3::Zero();
  const Vector3f h = (wi + wo).normalized();
  if (!(h.z() > 0)) return Color3::Zero();
  const float lobe = (exponent_ + 2.0f) / (8.0f * kPi) * std::pow(std::max(h.z(), 0.0f), exponent_);
  return sanitize(albedo_.eval(q) * lobe);
}

float BlinnPhong::pdf(const TextureQuery&, const Vector3f& wi, const Vector3f& wo) const {
  if (wi.z() <= 0 || wo.z() <= 0) return 0;
  const Vector3f h = (wi + wo).normalized();
  const float dot = wo.dot(h);
  if (!(dot > 0)) return 0;
  const float pdfH = (exponent_ + 1.0f) * kInv2Pi * std::pow(std::max(h.z(), 0.0f), exponent_);
  return sanitize(pdfH / (4.0f * dot));
}

std::optional<BsdfSample> BlinnPhong::sample(const TextureQuery& q, const Vector3f& wi, float,
                                             const Point2f& u, TransportMode mode) const {
  if (wi.z() <= 0) return std::nullopt;
  const Vector3f h = warp::squareToPowerCosineLobe(u, exponent_);
  if (wi.dot(h) <= 0) return std::nullopt;  // reflects below the horizon
  const Vector3f wo = reflect(wi, h).normalized();
  if (wo.z() <= 0) return std::nullopt;
  return makeSample(wo, eval(q, wi, wo, mode), pdf(q, wi, wo), kReflection | kGlossy);
}

MaterialType blinnPhongType() {
  return {"blinnphong",
          {"blinn_phong", "blinn-phong"},
          "normalised Blinn-Phong lobe",
          declarations(kAlbedo.described("the reflected fraction of light, at most"),
                       kExponent.described("the lobe's sharpness: cos^exponent of the half "
                                           "vector's angle to the normal")),
          [](MaterialFactory& f, const JsonNode& node) -> std::shared_ptr<const Material> {
            TexturedColor albedo = f.parseAlbedo(node);
            const float exponent = node.get(kExponent);
            return std::make_shared<BlinnPhong>(std::move(albedo), exponent);
          }};
}

}  // namespace verity
