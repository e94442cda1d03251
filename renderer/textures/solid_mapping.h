// Where a solid (world-space) texture sits: its own frame, placed in the world by the
// texture's optional `transform` like a surface's, so that a pattern can move with the
// object it is on (pbrt's TextureMapping3D). Without a transform it costs nothing.
#pragma once

#include <optional>

#include "core/transform.h"
#include "params/key_declaration.h"

namespace verity {

class JsonNode;

class SolidMapping {
 public:
  SolidMapping() = default;
  explicit SolidMapping(const Transform& toWorld) : toTexture_(toWorld.inverse()) {}

  Point3f operator()(const Point3f& world) const {
    return toTexture_ ? toTexture_->point(world) : world;
  }

 private:
  std::optional<Transform> toTexture_;
};

// A solid texture's optional "transform", read from its object `node`.
SolidMapping parseSolidMapping(const JsonNode& node);
// The declaration of that key, for the solid textures' registry entries.
KeyDeclaration solidTransformKey();

}  // namespace verity
