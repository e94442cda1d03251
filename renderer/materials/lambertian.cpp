#include "materials/lambertian.h"

#include "materials/material_factory.h"
#include "materials/material_keys.h"
#include "sampling/warp.h"

namespace verity {

Color3 Lambertian::eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
                        TransportMode) const {
  if (wi.z() <= 0 || wo.z() <= 0) return Color3::Zero();
  return albedo_.eval(q) * kInvPi;
}

float Lambertian::pdf(const TextureQuery&, const Vector3f& wi, const Vector3f& wo) const {
  if (wi.z() <= 0) return 0;
  return warp::squareToCosineHemispherePdf(wo);
}

std::optional<BsdfSample> Lambertian::sample(const TextureQuery& q, const Vector3f& wi, float,
                                             const Point2f& u, TransportMode) const {
  if (wi.z() <= 0) return std::nullopt;
  BsdfSample s;
  s.wo = warp::squareToCosineHemisphere(u);
  s.pdf = warp::squareToCosineHemispherePdf(s.wo);
  if (s.pdf <= 0) return std::nullopt;
  s.weight = albedo_.eval(q);
  s.lobe = kReflection | kDiffuse;
  return s;
}

MaterialType lambertianType() {
  return {"lambertian",
          {},
          "ideal diffuse reflection",
          declarations(kAlbedo),
          [](MaterialFactory& f, const JsonNode& node) -> std::shared_ptr<const Material> {
            return std::make_shared<Lambertian>(f.parseAlbedo(node));
          }};
}

}  // namespace verity
