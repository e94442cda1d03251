// One entry of the material registry (material_registry.h): a type's canonical name in the
// scene format, its other spellings, a one-line description for help and errors, the keys
// its JSON object takes, and the function that builds the material from that object. Each
// material's own file defines its entry (lambertianType() in lambertian.cpp, ...), next to the
// class it builds.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "params/key_declaration.h"

namespace verity {

class JsonNode;
class Material;
class MaterialFactory;

struct MaterialType {
  // Reads the type's keys from `node`; the factory supplies albedos, textures, named
  // materials and warnings. Unknown keys are rejected by the factory afterwards.
  using Build = std::shared_ptr<const Material> (*)(MaterialFactory& factory, const JsonNode& node);
  std::string name;                  // canonical; looked up by the rule of params/registry.h
  std::vector<std::string> aliases;  // other spellings of the same type
  std::string description;           // one line: what it is
  KeyList keys;                      // besides "type" and "name" (materialCommonKeys())
  Build build;
};

}  // namespace verity
