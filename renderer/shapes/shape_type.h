// One entry of the shape registry (shape_registry.h): a surface type's name in the scene
// format, a one-line description, the keys its JSON object takes, and the function that
// builds the shape from that object. Each shape's own file defines its entry (sphereType() in
// sphere.cpp, ...), next to the class it builds.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/transform.h"
#include "params/key_declaration.h"

namespace verity {

class JsonNode;
class Shape;

struct ShapeType {
  // Reads the type's own keys from `node`; `toWorld` is the surface's transform composed with
  // its groups'. The scene loader reads "type", "transform" and "material".
  using Build = std::unique_ptr<Shape> (*)(const JsonNode& node, const Transform& toWorld);
  std::string name;
  std::vector<std::string> aliases;  // other spellings of the same type
  std::string description;
  KeyList keys;  // besides surfaceCommonKeys() and "material"
  Build build;
};

}  // namespace verity
