#include "materials/material_keys.h"

#include "materials/material_params.h"

namespace verity {

KeyDeclaration albedoKey(const std::string& meaning) {
  return {"albedo", {},     ValueType::Texture, "each channel >= 0; above 1 is warned of",
          "0.8",    meaning};
}

KeyDeclaration distributionKey() {
  return {"distribution",    {},
          ValueType::String, "\"ggx\" or \"beckmann\"",
          "\"ggx\"",         "the microfacet normal distribution (Walter et al. 2007)"};
}

KeyDeclaration alphaKey(const std::string& name, const std::string& alias, const std::string& def) {
  return {name,
          {alias},
          ValueType::Number,
          kAlphaRange.interval(),
          def,
          "microfacet roughness α (the distribution's width; not squared). \"" + name +
              "\" and \"" + alias + "\" are two spellings of this one key: give one"};
}

KeyDeclaration samplingKey() {
  return {
      "sampling",
      {},
      ValueType::String,
      "\"visible\" or \"normals\"",
      "\"visible\"",
      "how microfacet normals are sampled: the normals visible from the incoming direction "
      "(Heitz and d'Eon 2014), or all normals by D(m)·cos θm; the same expected image, different "
      "noise"};
}

}  // namespace verity
