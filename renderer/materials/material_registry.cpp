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
const std::vector<MaterialType>& materialTypes() {
  static const std::vector<MaterialType> types = {
      lambertianType(),      diffuseLightType(), metalType(),    dielectricType(),
      phongType(),           blinnPhongType(),   beckmannType(), ggxType(),
      roughDielectricType(), orenNayarType(),    blendType(),
  };
  return types;
}

const KeyList& materialCommonKeys() {
  static const KeyList keys = {
      {"type",
       {},
       ValueType::String,
       "a type's name or other spelling (any letter case)",
       "required",
       "the material type"},
      {"name",
       {},
       ValueType::String,
       "unique in the file",
       "required in \"materials\", else none",
       "the name by which surfaces, and blends listed after it, refer to this material"}};
  return keys;
}

const MaterialType* findMaterialType(const std::string& spelling) {
  for (const MaterialType& t : materialTypes()) {
    if (t.name == spelling) return &t;
    for (const std::string& alias : t.aliases)
      if (alias == spelling) return &t;
  }
  return nullptr;
}

std::string materialTypeList() {
  std::string list;
  for (const MaterialType& t : materialTypes()) list += (list.empty() ? "" : ", ") + t.name;
  return list;
}

std::string materialTypeHelp() {
  std::string help;
  for (const MaterialType& t : materialTypes()) {
    std::string names = t.name;
    if (!t.aliases.empty()) {
      names += " (";
      for (size_t i = 0; i < t.aliases.size(); ++i) names += (i ? ", " : "") + t.aliases[i];
      names += ")";
    }
    std::string keys;
    for (const KeyDeclaration& k : t.keys)
      keys += (keys.empty() ? "; " : ", ") + k.name + " (" + k.defaultValue + ")";
    help += "  " + names + ": " + t.description + keys + "\n";
  }
  return help;
}

}  // namespace verity
