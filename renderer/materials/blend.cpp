#include "materials/blend.h"

#include "materials/material_factory.h"
#include "materials/sample_util.h"

namespace verity {

float Blend::amount(const TextureQuery& q) const {
  const float t = amount_.evalScalar(q);
  return std::isfinite(t) ? std::clamp(t, 0.0f, 1.0f) : 0.0f;
}

Color3 Blend::eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
                   TransportMode mode) const {
  const float t = amount(q);
  Color3 f = Color3::Zero();
  if (t < 1) f += (1 - t) * a_->eval(q, wi, wo, mode);
  if (t > 0) f += t * b_->eval(q, wi, wo, mode);
  return sanitize(f);
}

float Blend::pdf(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo) const {
  const float t = amount(q);
  float p = 0;
  if (t < 1) p += (1 - t) * a_->pdf(q, wi, wo);
  if (t > 0) p += t * b_->pdf(q, wi, wo);
  return sanitize(p);
}

std::optional<BsdfSample> Blend::sample(const TextureQuery& q, const Vector3f& wi, float uLobe,
                                        const Point2f& u, TransportMode mode) const {
  const float t = amount(q);
  // Reuse uLobe for the chosen material's own lobe choice, rescaled to [0, 1).
  const bool pickB = uLobe < t;
  const float uRest = pickB ? uLobe / t : (uLobe - t) / (1 - t);
  const Material& chosen = pickB ? *b_ : *a_;
  std::optional<BsdfSample> s =
      chosen.sample(q, wi, std::clamp(uRest, 0.0f, kOneMinusEpsilon), u, mode);
  if (!s) return std::nullopt;
  if (s->isDelta()) {
    s->pdf *= pickB ? t : 1 - t;
    return s;
  }
  return makeSample(s->wo, eval(q, wi, s->wo, mode), pdf(q, wi, s->wo), s->lobe, s->eta);
}

namespace {
const KeyDeclaration kBlendA{"a",
                             {},
                             ValueType::Material,
                             "a non-emitting material defined earlier in the file",
                             "required",
                             "the material weighted by 1 - amount: the name of a material listed "
                             "earlier in \"materials\", or an inline material object"};
const KeyDeclaration kBlendB{"b",        {},         ValueType::Material,
                             "as for a", "required", "the material weighted by amount"};
const Key<TexturedColor> kAmount{.name = "amount",
                                 .defaultValue = TexturedColor(Color3::Constant(0.5f)),
                                 .allowed = "[0, 1]; a texture is clamped to it",
                                 .meaning = "the weight of b (the mean of the channels)"};
}  // namespace

MaterialType blendType() {
  return {"blend",
          {},
          "(1 - amount)·a + amount·b",
          declarations(kBlendA, kBlendB, kAmount),
          [](MaterialFactory& f, const JsonNode& node) -> std::shared_ptr<const Material> {
            auto a = f.reference(node[kBlendA]);
            auto b = f.reference(node[kBlendB]);
            for (const auto& [key, material] :
                 {std::pair{&kBlendA, a.get()}, std::pair{&kBlendB, b.get()}})
              if (material->isEmitter())
                node[*key].fail(
                    "a blend cannot contain an emitter: only a surface whose material is a "
                    "\"diffuse light\" emits; give the light its own surface");
            TexturedColor amount = f.textures().parse(node, kAmount, "the blend amount");
            if (amount.isConstant() && !(amount.constant() <= 1).all())
              node[kAmount].fail("the blend amount must lie in [0, 1]");
            return std::make_shared<Blend>(std::move(a), std::move(b), std::move(amount));
          }};
}

}  // namespace verity
