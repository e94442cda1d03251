#include "materials/material_registry.h"

#include "materials/blend.h"
#include "materials/blinn_phong.h"
#include "materials/dielectric.h"
#include "materials/diffuse_light.h"
#include "materials/lambertian.h"
#include "materials/mirror.h"
#include "materials/oren_nayar.h"
#include "materials/phong.h"
#include "materials/rough_conductor.h"
#include "materials/rough_dielectric.h"

namespace verity {

// An explicit list rather than self-registering static objects (Nori's NORI_REGISTER_CLASS):
// verity_renderer is a static library, and the linker drops an object file that nothing
// references, together with the registrar it holds; the order in which static objects of
// different files are initialised is unspecified as well. A function-local table is built
// on first use, in a fixed order. A new type adds its entry function here.
const Registry<MaterialType>& materialTypes() {
  static const Registry<MaterialType> types("material type", {
                                                                 lambertianType(),
                                                                 diffuseLightType(),
                                                                 metalType(),
                                                                 dielectricType(),
                                                                 phongType(),
                                                                 blinnPhongType(),
                                                                 beckmannType(),
                                                                 ggxType(),
                                                                 roughDielectricType(),
                                                                 orenNayarType(),
                                                                 blendType(),
                                                             });
  return types;
}

const KeyList& materialCommonKeys() {
  static const KeyList keys = {
      materialTypes().typeKey(),
      {"name",
       {},
       ValueType::String,
       "unique in the file",
       "required in \"materials\", else none",
       "the name by which surfaces, and blends listed after it, refer to this material"}};
  return keys;
}

}  // namespace verity
