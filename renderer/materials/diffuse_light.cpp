#include "materials/diffuse_light.h"

#include "materials/material_factory.h"

namespace verity {

MaterialType diffuseLightType() {
  return {"diffuse_light",
          {"diffuse light"},
          "area light, constant radiance from the front side",
          {{"emit",
            {},
            ValueType::Rgb,
            "each channel >= 0, not all 0 (warned of)",
            "1",
            "the radiance emitted from the front side (the side the surface's normal faces)"}},
          [](MaterialFactory& f, const JsonNode& node) -> std::shared_ptr<const Material> {
            const Color3 emit = node.getVector3({"emit"}, Vector3f::Ones()).array();
            if (!(emit >= 0).all()) node[{"emit"}].fail("emitted radiance must not be negative");
            if ((emit == 0).all())
              f.warn(node.warning("a diffuse light whose emit is 0 emits nothing"));
            return std::make_shared<DiffuseLight>(emit);
          }};
}

}  // namespace verity
