#include "materials/material_keys.h"

namespace verity {

Key<float> alphaKey(const std::string& name, const std::string& alias, float def) {
  return {.name = name,
          .aliases = {alias},
          .defaultValue = def,
          .allowed = kAlphaRange,
          .meaning = "microfacet roughness α (the distribution's width; not squared). \"" + name +
                     "\" and \"" + alias + "\" are two spellings of this one key: give one"};
}

}  // namespace verity
