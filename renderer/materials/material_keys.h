// Declarations of the keys that several material types share (their readers are in
// material_factory.h and material_params.h), for the types' registry entries.
#pragma once

#include <string>

#include "params/key_declaration.h"

namespace verity {

// "albedo", a texture (0.8 when absent); `meaning` says what it scales in this type.
KeyDeclaration albedoKey(const std::string& meaning);
// "distribution": "ggx" or "beckmann".
KeyDeclaration distributionKey();
// The microfacet roughness α, spelled `name` or `alias`, with default `def`.
KeyDeclaration alphaKey(const std::string& name, const std::string& alias, const std::string& def);
// "sampling": "visible" or "normals".
KeyDeclaration samplingKey();

}  // namespace verity
