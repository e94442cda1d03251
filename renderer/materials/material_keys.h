// The keys that several material types share, each declared once: its default, the values
// allowed and what it means. A type lists them in its registry entry (described() gives a
// shared key the type's own words) and its build function reads them by the same object.
#pragma once

#include <string>

#include "materials/microfacet.h"
#include "params/key.h"
#include "textures/texture_factory.h"

namespace verity {

// Microfacet roughness α (ggx, beckmann, rough_dielectric): below kMinAlpha the lobe is far
// narrower than a pixel and its formulas lose precision (use mirror or dielectric); above 4
// it is rougher than any measured surface, and far above, its terms overflow and render black.
inline constexpr Range kAlphaRange{MicrofacetDistribution::kMinAlpha, 4.0f};
// Imaginary part κ of a conductor's index: non-negative, at most 100 (metals' κ below 10).
inline constexpr Range kExtinctionRange{0.0f, 100.0f};

// "albedo": what it scales depends on the type (described()). The factory reads it
// (MaterialFactory::parseAlbedo) and warns of a value above 1.
inline const Key<TexturedColor> kAlbedo{.name = "albedo",
                                        .defaultValue = TexturedColor(Color3::Constant(0.8f)),
                                        .allowed = "each channel >= 0; above 1 is warned of",
                                        .meaning = "the fraction of light reflected"};

// Real part of an index of refraction (dielectrics, conductors' η): positive, at most 100
// (diamond is 2.4, conductors' η below 10). The dielectrics' key; conductors' η is an RGB.
inline constexpr Range kIorRange{0.0f, 100.0f, true, false};
inline const Key<float> kIor{
    .name = "ior",
    .defaultValue = 1.5f,
    .allowed = kIorRange,
    .meaning = "index of refraction inside (behind the normal) over outside"};

// Phong and Blinn-Phong exponents: 0 is a cosine lobe, 1e6 a lobe far narrower than a pixel.
inline const Key<float> kExponent{.name = "exponent",
                                  .defaultValue = 10,
                                  .allowed = {0.0f, 1e6f},
                                  .meaning = "the lobe's sharpness"};

inline const Key<MicrofacetType> kDistribution{
    .name = "distribution",
    .defaultValue = MicrofacetType::GGX,
    .allowed = {{"ggx", MicrofacetType::GGX}, {"beckmann", MicrofacetType::Beckmann}},
    .meaning = "the microfacet normal distribution (Walter et al. 2007)"};

inline const Key<MicrofacetSampling> kSampling{
    .name = "sampling",
    .defaultValue = MicrofacetSampling::Visible,
    .allowed = {{"visible", MicrofacetSampling::Visible}, {"normals", MicrofacetSampling::Normals}},
    .meaning =
        "how microfacet normals are sampled: the normals visible from the incoming "
        "direction (Heitz and d'Eon 2014), or all normals by D(m)·cos θm; the same "
        "expected image, different noise"};

// The microfacet roughness α, spelled `name` or `alias`, with default `def`: DIRT's
// conductors call it "ab", the rough dielectric "alpha".
Key<float> alphaKey(const std::string& name, const std::string& alias, float def);

}  // namespace verity
