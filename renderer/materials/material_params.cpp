#include "materials/material_params.h"

namespace verity {

MicrofacetSampling parseSampling(const JsonNode& node) {
  auto s = node.find({"sampling"});
  if (!s) return MicrofacetSampling::Visible;
  const std::string mode = s->asString();
  if (mode == "visible") return MicrofacetSampling::Visible;
  if (mode == "normals") return MicrofacetSampling::Normals;
  s->fail("unknown sampling mode \"" + mode + "\" (expected \"visible\" or \"normals\")");
}

MicrofacetType parseDistribution(const JsonNode& node) {
  auto d = node.find({"distribution"});
  if (!d) return MicrofacetType::GGX;
  const std::string name = d->asString();
  if (name == "ggx") return MicrofacetType::GGX;
  if (name == "beckmann") return MicrofacetType::Beckmann;
  d->fail("unknown microfacet distribution \"" + name + "\" (expected \"ggx\" or \"beckmann\")");
}

}  // namespace verity
