// One entry of the texture registry (texture_registry.h): a texture type's name in the scene
// format, a one-line description, the keys its JSON object takes, and the function that
// builds the texture from that object. Each texture's own file defines its entry
// (checkerTextureType() in checker.cpp, ...), next to the class it builds.
#pragma once

#include <string>
#include <vector>

#include "params/key_declaration.h"
#include "textures/texture.h"

namespace verity {

class JsonNode;
class TextureFactory;

struct TextureType {
  // Reads the type's own keys from `node`; `factory` reads the textures nested in it and keeps
  // the images decoded so far; `quantity` names the value in errors ("roughness must not be
  // negative"). The factory reads "type" and rejects unknown keys.
  using Build = TexturedColor (*)(const JsonNode& node, TextureFactory& factory,
                                  const std::string& quantity);
  std::string name;
  std::vector<std::string> aliases;  // other spellings of the same type
  std::string description;
  KeyList keys;  // besides textureCommonKeys()
  Build build;
};

}  // namespace verity
