#include "materials/diffuse_light.h"

#include "materials/material_factory.h"
#include "params/key.h"

namespace verity {

namespace {

const Key<Color3> kEmit{
    .name = "emit",
    .defaultValue = Color3::Ones(),
    .allowed = Range::nonNegative(),
    .meaning = "the radiance emitted from the front side (the side the surface's normal faces)",
    .alsoAllowed = "not all 0 (warned of)"};

}  // namespace

MaterialType diffuseLightType() {
  return {"diffuse_light",
          {"diffuse light"},
          "area light, constant radiance from the front side",
          declarations(kEmit),
          [](MaterialFactory& f, const JsonNode& node) -> std::shared_ptr<const Material> {
            const Color3 emit = node.get(kEmit);
            if ((emit == 0).all())
              f.warn(node.warning("a diffuse light whose emit is 0 emits nothing"));
            return std::make_shared<DiffuseLight>(emit);
          }};
}

}  // namespace verity
