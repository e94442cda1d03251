// Reads the scene format's transforms: one object or an array applied first to last.
#pragma once

#include "core/transform.h"
#include "scene/json_node.h"

namespace verity {

Transform parseTransform(const JsonNode& node);
// Member "transform" of `parent`, or the identity.
Transform parseOptionalTransform(const JsonNode& parent);

}  // namespace verity
