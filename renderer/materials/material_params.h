// Readers of the JSON keys that several material types share.
#pragma once

#include "materials/microfacet.h"
#include "params/json_node.h"

namespace verity {

// Stated ranges of the parameters several material types share; a value outside is an error
// naming the key (JsonNode::getFloat). Each type's own parameters have their ranges beside its
// registry entry.
//
// Microfacet roughness α (ggx, beckmann, rough_dielectric): below kMinAlpha the lobe is far
// narrower than a pixel and its formulas lose precision (use mirror or dielectric); above 4
// it is rougher than any measured surface, and far above, its terms overflow and render black.
inline constexpr Range kAlphaRange{MicrofacetDistribution::kMinAlpha, 4.0f};
// Real part of an index of refraction (dielectrics, conductors' η): positive, at most 100
// (diamond is 2.4, conductors' η below 10).
inline constexpr Range kIorRange{0.0f, 100.0f, true, false};
// Imaginary part κ of a conductor's index: non-negative, at most 100 (metals' κ below 10).
inline constexpr Range kExtinctionRange{0.0f, 100.0f};
// Phong and Blinn-Phong exponents: 0 is a cosine lobe, 1e6 a lobe far narrower than a pixel.
inline constexpr Range kExponentRange{0.0f, 1e6f};

// "sampling": "visible" (the default) or "normals", how microfacet normals are sampled.
MicrofacetSampling parseSampling(const JsonNode& node);
// "distribution": "ggx" (the default) or "beckmann".
MicrofacetType parseDistribution(const JsonNode& node);

}  // namespace verity
