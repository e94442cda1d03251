#include "textures/solid_mapping.h"

#include "params/json_node.h"
#include "params/transform_parser.h"

namespace verity {

SolidMapping parseSolidMapping(const JsonNode& node) {
  return node.has({"transform"}) ? SolidMapping(parseOptionalTransform(node)) : SolidMapping();
}

KeyDeclaration solidTransformKey() {
  return {"transform",
          {},
          ValueType::Transform,
          "invertible",
          "identity",
          "places the texture's own frame in the world, so that the pattern can move with "
          "the object it is on"};
}

}  // namespace verity
