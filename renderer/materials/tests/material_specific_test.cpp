// Behaviour specific to single materials, and the factory.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "materials/fresnel.h"
#include "materials/oren_nayar.h"
#include "materials/tests/material_test_util.h"

namespace verity::test::material_specific_test {
namespace {

TextureQuery q;

TEST(Mirror, ReflectsWithAlbedo) {
  auto m = makeMaterial(R"({"type":"metal","albedo":[0.9,0.5,0.2],"roughness":0})");
  EXPECT_EQ(m->lobes(), kReflection | kSpecular);
  const Vector3f wi = direction(40);
  auto s = m->sample(q, wi, 0.3f, Point2f(0.2f, 0.7f), TransportMode::Radiance);
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->isDelta());
  EXPECT_TRUE(((s->weight - Color3(0.9f, 0.5f, 0.2f)).abs() < 1e-6f).all());
  EXPECT_TRUE((s->wo - Vector3f(-wi.x(), -wi.y(), wi.z())).norm() < 1e-6f);
  EXPECT_TRUE(isBlack(m->eval(q, wi, s->wo, TransportMode::Radiance)));
  EXPECT_EQ(m->pdf(q, wi, s->wo), 0.0f);
  EXPECT_FALSE(
      m->sample(q, direction(40, 0.7, true), 0.3f, Point2f(0.2f, 0.7f), TransportMode::Radiance));
}

// The reflection probability is the Fresnel reflectance (binomial bound), refracted
// radiance is scaled by 1/η² and importance is not, η is reported, and beyond the critical
// angle every sample reflects.
TEST(Dielectric, FresnelChoiceAndScaling) {
  for (float ior : {1.5f, 2.4f}) {
    auto m = makeMaterial(fmt::format(R"({{"type":"dielectric","ior":{}}})", ior));
    for (bool inside : {false, true}) {
      const Vector3f wi = direction(inside ? 30 : 60, 0.7, inside);
      const float f = fresnelDielectric(wi.z(), ior);
      Rng rng(21);
      const int n = 20000;
      int reflected = 0;
      for (int i = 0; i < n; ++i) {
        for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
          auto s = m->sample(q, wi, rng.next(), rng.next2(), mode);
          ASSERT_TRUE(s);
          if (mode == TransportMode::Radiance && (s->lobe & kReflection)) ++reflected;
          if (s->lobe & kTransmission) {
            const float etaRel = inside ? 1 / ior : ior;
            EXPECT_FLOAT_EQ(s->eta, etaRel);
            EXPECT_FLOAT_EQ(s->pdf, 1 - f);
            const float expected = mode == TransportMode::Radiance ? 1 / (etaRel * etaRel) : 1.0f;
            EXPECT_FLOAT_EQ(s->weight.x(), expected);
            // Snell: η_i sin θi = η_t sin θt.
            EXPECT_NEAR(std::sqrt(1 - sqr(wi.z())), etaRel * std::sqrt(1 - sqr(s->wo.z())), 1e-5f);
          } else {
            EXPECT_FLOAT_EQ(s->weight.x(), 1.0f);
            EXPECT_FLOAT_EQ(s->pdf, f);
          }
        }
      }
      const double se = std::sqrt(f * (1 - f) / n);
      EXPECT_NEAR(double(reflected) / n, f, kSigmas * se + 1e-9);
    }
    // Inside, beyond the critical angle: total internal reflection.
    const Vector3f grazing = direction(80, 0.7, true);
    for (float u : {0.0f, 0.5f, kOneMinusEpsilon}) {
      auto s = m->sample(q, grazing, u, Point2f(0.5f, 0.5f), TransportMode::Radiance);
      ASSERT_TRUE(s);
      EXPECT_TRUE(s->lobe & kReflection);
      EXPECT_LT(s->wo.z(), 0);
    }
  }
}

// Rough dielectric: the transmitted weight in radiance mode is the importance-mode weight
// times (η_wi/η_wo)², for the same sample; an index-matched interface is a delta pass.
TEST(RoughDielectric, RadianceScalingAndIndexMatched) {
  auto m = makeMaterial(R"({"type":"rough_dielectric","alpha":0.3,"ior":1.5})");
  Rng rng(22);
  for (bool inside : {false, true}) {
    const Vector3f wi = direction(35, 0.7, inside);
    int transmitted = 0;
    for (int i = 0; i < 2000; ++i) {
      const float uLobe = rng.next();
      const Point2f u = rng.next2();
      auto r = m->sample(q, wi, uLobe, u, TransportMode::Radiance);
      auto p = m->sample(q, wi, uLobe, u, TransportMode::Importance);
      ASSERT_EQ(bool(r), bool(p));
      if (!r || !(r->lobe & kTransmission)) continue;
      ++transmitted;
      const float etaRel = inside ? 1 / 1.5f : 1.5f;
      EXPECT_FLOAT_EQ(r->eta, etaRel);
      EXPECT_NEAR(r->weight.x(), p->weight.x() / (etaRel * etaRel), 1e-5f * p->weight.x());
    }
    EXPECT_GT(transmitted, 1000);
  }
  auto matched = makeMaterial(R"({"type":"rough_dielectric","alpha":0.3,"ior":1.0001})");
  EXPECT_TRUE(matched->hasDeltaLobe());
  auto s = matched->sample(q, direction(30), 0.5f, Point2f(0.3f, 0.3f), TransportMode::Radiance);
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->isDelta());
  EXPECT_LT((s->wo + direction(30)).norm(), 1e-3f);
}

// σ = 0 is Lambertian; at grazing incidence the albedo reaches A + B/2, the model's known
// energy gain for small σ (the closed form derived in oren_nayar.h).
TEST(OrenNayar, LimitsOfTheModel) {
  auto on = makeMaterial(R"({"type":"oren-nayar","albedo":0.5,"sigma":0})");
  Rng rng(23);
  for (int i = 0; i < 100; ++i) {
    const Vector3f wi = warp::squareToCosineHemisphere(rng.next2());
    const Vector3f wo = warp::squareToCosineHemisphere(rng.next2());
    EXPECT_NEAR(on->eval(q, wi, wo, TransportMode::Radiance).x(), 0.5f * kInvPi, 1e-6f);
  }
  const float sigma = 0.2f;
  OrenNayar model(TexturedColor(Color3::Ones()), sigma);
  const Vector3f wi = direction(89.99);
  MeanEstimate albedo;
  for (int i = 0; i < 200000; ++i) {
    auto s = model.sample(q, wi, rng.next(), rng.next2(), TransportMode::Radiance);
    albedo.add(s ? s->weight.x() : 0.0);
  }
  const double expected = model.A() + model.B() / 2;
  EXPECT_GT(expected, 1.0);
  EXPECT_NEAR(albedo.mean(), expected, kSigmas * albedo.standardError() + 1e-3);
}

// Blend: eval and pdf are the mixtures, a delta sample of b keeps b's weight with its
// density scaled by the amount.
TEST(Blend, MixesValuesAndDensities) {
  auto a = makeMaterial(R"({"type":"lambertian","albedo":0.6})");
  auto b = makeMaterial(R"({"type":"ggx","albedo":1,"ab":0.3})");
  auto blend = makeMaterial(
      R"({"type":"blend","a":{"type":"lambertian","albedo":0.6},"b":{"type":"ggx","albedo":1,"ab":0.3},"amount":0.25})");
  EXPECT_EQ(blend->lobes(), a->lobes() | b->lobes());
  Rng rng(24);
  for (int i = 0; i < 200; ++i) {
    const Vector3f wi = warp::squareToCosineHemisphere(rng.next2());
    const Vector3f wo = warp::squareToCosineHemisphere(rng.next2());
    const Color3 expected = 0.75f * a->eval(q, wi, wo, TransportMode::Radiance) +
                            0.25f * b->eval(q, wi, wo, TransportMode::Radiance);
    EXPECT_NEAR(blend->eval(q, wi, wo, TransportMode::Radiance).x(), expected.x(),
                1e-5f * (1 + expected.x()));
    EXPECT_NEAR(blend->pdf(q, wi, wo), 0.75f * a->pdf(q, wi, wo) + 0.25f * b->pdf(q, wi, wo),
                1e-5f * (1 + b->pdf(q, wi, wo)));
  }
  auto withMirror = makeMaterial(
      R"({"type":"blend","a":{"type":"lambertian"},"b":{"type":"metal","albedo":0.7,"roughness":0},"amount":0.4})");
  auto s = withMirror->sample(q, direction(20), 0.1f, Point2f(0.5f, 0.5f), TransportMode::Radiance);
  ASSERT_TRUE(s && s->isDelta());
  EXPECT_FLOAT_EQ(s->weight.x(), 0.7f);
  EXPECT_FLOAT_EQ(s->pdf, 0.4f);
}

TEST(MaterialFactory, SpellingsAndFlags) {
  for (
      const char* json :
      {R"({"type":"blinnphong"})", R"({"type":"blinn_phong"})", R"({"type":"blinn-phong"})",
       R"({"type":"phong","exponent":30})", R"({"type":"oren_nayar"})", R"({"type":"oren-nayar"})",
       R"({"type":"rough dielectric"})", R"({"type":"roughdielectric"})",
       R"({"type":"rough_dielectric","distribution":"beckmann","alpha":0.2,"ior":1.33,"sampling":"normals"})",
       R"({"type":"beckmann","ab":0.3,"ior":0.2,"ext":3,"sampling":"normals"})",
       R"({"type":"ggx","alpha":0.3})", R"({"type":"Dielectric","ior":1.5})"}) {
    EXPECT_NO_THROW(makeMaterial(json)) << json;
  }
  EXPECT_FALSE(makeMaterial(R"({"type":"ggx"})")->isTextured());
  EXPECT_TRUE(
      makeMaterial(R"({"type":"metal","roughness":{"type":"checker","even":0.1,"odd":0.5}})")
          ->isTextured());
  EXPECT_TRUE(
      makeMaterial(
          R"({"type":"blend","a":{"type":"lambertian"},"b":{"type":"phong"},"amount":{"type":"checker"}})")
          ->isTextured());
  EXPECT_EQ(makeMaterial(R"({"type":"metal","roughness":0.2})")->lobes(), kReflection | kGlossy);
  EXPECT_EQ(makeMaterial(R"({"type":"dielectric","ior":1.5})")->lobes(),
            kReflection | kTransmission | kSpecular);
}

TEST(MaterialFactory, RejectsBadParameters) {
  for (const char* json :
       {R"({"type":"ggx","ab":-0.1})", R"({"type":"beckmann","ior":0})",
        R"({"type":"beckmann","ext":-1})", R"({"type":"ggx","sampling":"bogus"})",
        R"({"type":"metal","roughness":-0.5})", R"({"type":"dielectric","ior":-1.5})",
        R"({"type":"dielectric","ior":0})", R"({"type":"rough_dielectric","alpha":-1})",
        R"({"type":"rough_dielectric","distribution":"phong"})",
        R"({"type":"rough_dielectric","ior":0})", R"({"type":"phong","exponent":-2})",
        R"({"type":"oren-nayar","sigma":-0.1})", R"({"type":"ggx","roughness":0.2})",
        R"({"type":"blend","a":{"type":"lambertian"}})",
        R"({"type":"blend","a":"nothing","b":{"type":"lambertian"}})",
        R"({"type":"blend","a":{"type":"lambertian"},"b":{"type":"lambertian"},"amount":2})",
        R"({"type":"dielectric","ior":1.5,"albedo":1})"}) {
    EXPECT_THROW(makeMaterial(json), VerityError) << json;
  }
  try {
    makeMaterial(R"({"type":"ggx","sampling":"bogus"})");
  } catch (const VerityError& e) {
    EXPECT_NE(std::string(e.what()).find("sampling"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace verity::test::material_specific_test
