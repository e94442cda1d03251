// Every texture type of the scene format, from one table: the texture factory looks types up
// here, and its "unknown texture type" error and docs/scene-format.md read their names and
// keys from here. A bare number or [r, g, b] is a constant too (the factory reads it).
#pragma once

#include <string>
#include <vector>

#include "params/registry.h"
#include "textures/texture_type.h"

namespace verity {

// In the order of the table in texture_registry.cpp.
const Registry<TextureType>& textureTypes();
// The keys every texture object takes: "type".
const KeyList& textureCommonKeys();

}  // namespace verity
