// Every material type of the scene format, from one table: the factory looks types up
// here, and help text, the "unknown material type" error and the coverage tests of the
// chi-square suite and the stability grid read their names from here.
#pragma once

#include <string>
#include <vector>

#include "materials/material_type.h"

namespace verity {

// In the order of the table in material_registry.cpp.
const std::vector<MaterialType>& materialTypes();
// The keys every material object takes besides its type's: "type" and "name".
const KeyList& materialCommonKeys();
// The type with this name or alias (lower case, as JsonNode::type() gives it); null if none.
const MaterialType* findMaterialType(const std::string& spelling);
// "lambertian, diffuse_light, ...": the canonical names, for error messages.
std::string materialTypeList();
// One line per type: its names (aliases in parentheses), its description and its keys with
// their defaults.
std::string materialTypeHelp();

}  // namespace verity
