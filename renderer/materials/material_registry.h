// Every material type of the scene format, from one table: the factory looks types up
// here, and help text, the "unknown material type" error and the coverage tests of the
// chi-square suite and the stability grid read their names from here.
#pragma once

#include <string>
#include <vector>

#include "materials/material_type.h"
#include "params/registry.h"

namespace verity {

// In the order of the table in material_registry.cpp.
const Registry<MaterialType>& materialTypes();
// The keys every material object takes besides its type's: "type" and "name".
const KeyList& materialCommonKeys();
// The table's lookup, as the suites outside the renderer spell it.
inline const MaterialType* findMaterialType(std::string_view spelling) {
  return materialTypes().find(spelling);
}

}  // namespace verity
