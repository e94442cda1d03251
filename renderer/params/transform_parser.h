// Reads the scene format's transforms: one object or an array applied first to last.
#pragma once

#include "core/transform.h"
#include "params/json_node.h"

namespace verity {

Transform parseTransform(const JsonNode& node);
// The keys of one transform object: each object uses the keys of exactly one form (look-at,
// frame, translate, scale, axis-angle or matrix).
const KeyList& transformKeys();
// Member "transform" of `parent`, or the identity.
Transform parseOptionalTransform(const JsonNode& parent);

}  // namespace verity
