#include "materials/oren_nayar.h"

#include "core/frame.h"
#include "materials/material_factory.h"
#include "materials/material_keys.h"
#include "materials/sample_util.h"
#include "sampling/warp.h"

namespace verity {

OrenNayar::OrenNayar(TexturedColor albedo, float sigma) : albedo_(std::move(albedo)) {
  const float s2 = sigma * sigma;
  a_ = 1.0f - s2 / (2.0f * (s2 + 0.33f));
  b_ = 0.45f * s2 / (s2 + 0.09f);
}

Color3 OrenNayar::eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
                       TransportMode) const {
  if (wi.z() <= 0 || wo.z() <= 0) return Color3::Zero();
  const float sinI = Frame::sinTheta(wi), sinO = Frame::sinTheta(wo);
  float term = 0;
  if (sinI > 1e-6f && sinO > 1e-6f) {
    // cos(φi − φo) from the tangent components, without trigonometric calls.
    const float cosDPhi =
        std::clamp((wi.x() * wo.x() + wi.y() * wo.y()) / (sinI * sinO), -1.0f, 1.0f);
    // sin α·tan β: α belongs to the direction with the smaller cosine.
    const float sinAlphaTanBeta = wi.z() < wo.z() ? sinI * sinO / wo.z() : sinO * sinI / wi.z();
    term = std::max(0.0f, cosDPhi) * sinAlphaTanBeta;
  }
  return sanitize(albedo_.eval(q) * (kInvPi * (a_ + b_ * term)));
}

float OrenNayar::pdf(const TextureQuery&, const Vector3f& wi, const Vector3f& wo) const {
  if (wi.z() <= 0) return 0;
  return warp::squareToCosineHemispherePdf(wo);
}

std::optional<BsdfSample> OrenNayar::sample(const TextureQuery& q, const Vector3f& wi, float,
                                            const Point2f& u, TransportMode mode) const {
  if (wi.z() <= 0) return std::nullopt;
  const Vector3f wo = warp::squareToCosineHemisphere(u);
  return makeSample(wo, eval(q, wi, wo, mode), pdf(q, wi, wo), kReflection | kDiffuse);
}

// The facets' slope deviation in radians: beyond π/2 a deviation of facet angles means
// nothing (the model's A and B have long saturated).
const Key<float> kSigma{.name = "sigma",
                        .defaultValue = 0.35f,
                        .allowed = {0.0f, kPi / 2},
                        .meaning = "standard deviation of the facets' slope angle, in radians"};

MaterialType orenNayarType() {
  return {"oren-nayar",
          {"oren_nayar"},
          "rough diffuse reflection",
          declarations(kAlbedo.described("the reflectance of the facets"), kSigma),
          [](MaterialFactory& f, const JsonNode& node) -> std::shared_ptr<const Material> {
            TexturedColor albedo = f.parseAlbedo(node);
            const float sigma = node.get(kSigma);
            return std::make_shared<OrenNayar>(std::move(albedo), sigma);
          }};
}

}  // namespace verity
