// Readers of the JSON keys that several material types share.
#pragma once

#include "materials/microfacet.h"
#include "scene/json_node.h"

namespace verity {

// "sampling": "visible" (the default) or "normals", how microfacet normals are sampled.
MicrofacetSampling parseSampling(const JsonNode& node);
// "distribution": "ggx" (the default) or "beckmann".
MicrofacetType parseDistribution(const JsonNode& node);

}  // namespace verity
