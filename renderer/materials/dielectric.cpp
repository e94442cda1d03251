#include "materials/dielectric.h"

#include "materials/fresnel.h"
#include "materials/material_factory.h"
#include "materials/material_keys.h"

namespace verity {

std::optional<BsdfSample> sampleSmoothDielectric(const Vector3f& wi, float eta, float uLobe,
                                                 TransportMode mode) {
  const float cosThetaI = wi.z();
  const float f = fresnelDielectric(cosThetaI, eta);
  BsdfSample s;
  if (uLobe < f) {
    s.wo = Vector3f(-wi.x(), -wi.y(), wi.z());
    s.pdf = f;
    s.weight = Color3::Ones();  // F / F
    s.lobe = kReflection | kSpecular;
    return s;
  }
  // Relative index across the interface as seen from wi's side.
  const float etaRel = cosThetaI > 0 ? eta : 1.0f / eta;
  const Vector3f n = cosThetaI > 0 ? Vector3f::UnitZ() : Vector3f(-Vector3f::UnitZ());
  Vector3f wt;
  if (!refract(wi, n, etaRel, wt)) return std::nullopt;  // unreachable: TIR has f = 1
  s.wo = wt;
  s.pdf = 1.0f - f;
  const float scale = mode == TransportMode::Radiance ? 1.0f / (etaRel * etaRel) : 1.0f;
  s.weight = Color3::Constant(scale);  // (1 − F) / (1 − F), scaled
  s.lobe = kTransmission | kSpecular;
  s.eta = etaRel;
  return s;
}

MaterialType dielectricType() {
  return {"dielectric",
          {},
          "smooth glass, a delta reflection and refraction",
          declarations(kIor),
          [](MaterialFactory&, const JsonNode& node) -> std::shared_ptr<const Material> {
            return std::make_shared<Dielectric>(node.get(kIor));
          }};
}

}  // namespace verity
