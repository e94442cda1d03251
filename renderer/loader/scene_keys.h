// The keys of the objects the scene loader reads itself: the scene file's top level, the
// camera, a group of surfaces, and the keys every sampler object takes. The types with registries
// declare theirs in their entries (materials, shapes, backgrounds, textures, integrators,
// samplers); transforms in transform_parser.h.
#pragma once

#include "params/key_declaration.h"

namespace verity {

// The top-level object of a scene file.
const KeyList& sceneKeys();
// The "camera" object.
const KeyList& cameraKeys();
// A surface of type "group", besides surfaceCommonKeys() (shape_registry.h).
const KeyList& groupKeys();
// The keys of every "sampler" object, besides its type's (sampler_type.h): "type", and the
// sample count "samples", which the loader reads whatever the type.
const KeyList& samplerCommonKeys();

}  // namespace verity
