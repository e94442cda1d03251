#include "shapes/shape_registry.h"

#include "shapes/quad.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"

namespace verity {

// An explicit list, as materials' (material_registry.cpp): the renderer is a static library,
// whose unreferenced object files the linker drops, self-registration and all.
const std::vector<ShapeType>& shapeTypes() {
  static const std::vector<ShapeType> types = {sphereType(), quadType(), meshType(),
                                               triangleType()};
  return types;
}

const ShapeType* findShapeType(const std::string& name) {
  for (const ShapeType& t : shapeTypes())
    if (t.name == name) return &t;
  return nullptr;
}

std::string shapeTypeList() {
  std::string list;
  for (const ShapeType& t : shapeTypes()) list += (list.empty() ? "" : ", ") + t.name;
  return list;
}

const KeyList& surfaceCommonKeys() {
  static const KeyList keys = {
      {"type",
       {},
       ValueType::String,
       "a shape's name or \"group\" (any letter case)",
       "required",
       "the surface type"},
      {"transform",
       {},
       ValueType::Transform,
       "invertible",
       "identity",
       "places the surface's local frame in its parent's (the world's, or its group's)"}};
  return keys;
}

const KeyList& shapeCommonKeys() {
  static const KeyList keys = {
      {"material",
       {},
       ValueType::Material,
       "a name defined in \"materials\", or an object",
       "required",
       "the surface's material; a \"diffuse_light\" makes the surface an emitter"}};
  return keys;
}

}  // namespace verity
