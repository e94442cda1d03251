// Every shape type of the scene format's "surfaces", from one table: the scene loader looks
// types up here, and its "unknown surface type" error and docs/scene-format.md read their
// names and keys from here. A "group" is not a shape: the loader reads it.
#pragma once

#include <string>
#include <vector>

#include "params/registry.h"
#include "shapes/shape_type.h"

namespace verity {

// In the order of the table in shape_registry.cpp.
const Registry<ShapeType>& shapeTypes();
// The keys every surface takes, a group's included: "type" and "transform".
const KeyList& surfaceCommonKeys();
// The keys every shape takes besides its type's: "material".
const KeyList& shapeCommonKeys();

}  // namespace verity
