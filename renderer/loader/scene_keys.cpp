#include "loader/scene_keys.h"

#include "sampling/sampler_registry.h"

namespace verity {

const KeyList& sceneKeys() {
  using namespace scene_keys;
  static const KeyList keys = declarations(kCamera, kIntegrator, kSampler, kImageSamples,
                                           kBackground, kAccelerator, kMaterials, kSurfaces);
  return keys;
}

const KeyList& cameraKeys() {
  using namespace scene_keys;
  static const KeyList keys = declarations(kCameraTransform, kResolution, kVfov, kFdist, kAperture);
  return keys;
}

const KeyList& groupKeys() {
  static const KeyList keys = declarations(scene_keys::kChildren);
  return keys;
}

const KeyList& samplerCommonKeys() {
  static const KeyList keys = {samplerTypes().typeKey("\"" + samplerTypes().front().name + "\""),
                               scene_keys::kSamples.declaration()};
  return keys;
}

}  // namespace verity
