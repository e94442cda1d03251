#include "shapes/shape_registry.h"

#include "shapes/quad.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"

namespace verity {

// An explicit list, as materials' (material_registry.cpp): the renderer is a static library,
// whose unreferenced object files the linker drops, self-registration and all.
// A "group" is read by the scene loader, and named among the known surface types.
const Registry<ShapeType>& shapeTypes() {
  static const Registry<ShapeType> types(
      "surface type", {sphereType(), quadType(), meshType(), triangleType()}, {"group"});
  return types;
}

const KeyList& surfaceCommonKeys() {
  static const KeyList keys = {
      shapeTypes().typeKey(),
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
