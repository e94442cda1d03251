// Every texture type of the scene format, from one table: the texture factory looks types up
// here, and its "unknown texture type" error and docs/scene-format.md read their names and
// keys from here. A bare number or [r, g, b] is a constant too (the factory reads it).
#pragma once

#include <string>
#include <vector>

#include "textures/texture_type.h"

namespace verity {

// In the order of the table in texture_registry.cpp.
const std::vector<TextureType>& textureTypes();
// The type named `name` (lower case); null if none.
const TextureType* findTextureType(const std::string& name);
// "constant, checker, marble or image", for errors.
std::string textureTypeList();
// The keys every texture object takes: "type".
const KeyList& textureCommonKeys();

}  // namespace verity
