// Every background type of the scene format's "background" object, from one table: the scene
// loader looks types up here, and docs/scene-format.md reads their names and keys from here.
// A bare number or [r, g, b] is a constant background too (the scene loader reads it).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "lights/environment_light.h"
#include "params/key_declaration.h"
#include "params/registry.h"

namespace verity {

class JsonNode;

struct BackgroundType {
  using Build = std::unique_ptr<EnvironmentLight> (*)(const JsonNode& node);
  std::string name;
  std::vector<std::string> aliases;  // other spellings of the same type
  std::string description;
  KeyList keys;  // besides backgroundCommonKeys()
  Build build;
};

// In the order of the table in background_registry.cpp.
const Registry<BackgroundType>& backgroundTypes();
// The keys every background object takes: "type".
const KeyList& backgroundCommonKeys();

}  // namespace verity
