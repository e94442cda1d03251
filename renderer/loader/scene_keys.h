// The keys of the objects the scene loader reads itself: the scene file's top level, the
// camera, a group of surfaces, and the keys every sampler object takes. Each is declared once
// here: the loader reads it by this declaration and docs/scene-format.md prints it. The types
// with registries declare theirs beside their definitions (materials, shapes, backgrounds,
// textures, integrators, samplers); transforms in transform_parser.h.
#pragma once

#include "core/ray.h"
#include "params/key.h"
#include "params/key_declaration.h"

namespace verity::scene_keys {

// The top level. The objects' own readers read the values of the keys typed as objects.
inline const KeyDeclaration kCamera{"camera", {},         ValueType::Object,
                                    "",       "required", "the camera (see Camera)"};
inline const KeyDeclaration kIntegrator{"integrator",
                                        {},
                                        ValueType::Object,
                                        "",
                                        "{\"type\": \"path_tracer_mats\"}",
                                        "the integrator and its settings (see Integrators)"};
inline const KeyDeclaration kSampler{"sampler",
                                     {},
                                     ValueType::Object,
                                     "",
                                     "{\"type\": \"independent\"}",
                                     "the sample generator and the sample count (see Samplers)"};
// The most samples per pixel a scene may ask for.
inline constexpr IntRange kSampleCount{1, 1 << 24};
inline const Key<int> kImageSamples{
    .name = "image_samples",
    .defaultValue = 1,
    .allowed = kSampleCount,
    .meaning =
        "samples per pixel (DIRT's spelling); \"sampler\".\"samples\" may say it too, but "
        "only the same number"};
inline const KeyDeclaration kBackground{
    "background",   {},
    ValueType::Any, "a number, [r, g, b] or a background object",
    "0 (black)",    "radiance arriving from infinity where a ray escapes (see Backgrounds)"};
inline const KeyDeclaration kAccelerator{
    "accelerator",
    {},
    ValueType::Any,
    "",
    "none",
    "DIRT's choice of acceleration structure: accepted and ignored (Embree serves all)"};
inline const KeyDeclaration kMaterials{
    "materials",
    {},
    ValueType::Array,
    "material objects, each with a unique \"name\"",
    "[]",
    "the named materials, in order: a blend may name only materials listed before it"};
inline const KeyDeclaration kSurfaces{
    "surfaces",        {},   ValueType::Array,
    "surface objects", "[]", "the shapes and groups of the scene (see Surfaces)"};

// The camera.
inline const KeyDeclaration kCameraTransform{
    "transform",
    {},
    ValueType::Transform,
    "a similarity (no shear or non-uniform scale)",
    "identity",
    "places the camera: it looks down its local -z axis with +y up; a look-at is usual"};
// The most pixels an image may have (8192²): the film keeps several channels per pixel.
inline constexpr int64_t kMaxPixels = int64_t{1} << 26;
inline constexpr int kMaxImageSide = 1 << 15;
inline const Key<Vector2i> kResolution{.name = "resolution",
                                       .defaultValue = Vector2i(512, 512),
                                       .allowed = {1, kMaxImageSide},
                                       .meaning = "the image size in pixels",
                                       .alsoAllowed = "at most 8192 × 8192 pixels in all"};
inline const Key<float> kVfov{.name = "vfov",
                              .defaultValue = 90,
                              .allowed = {0, 180, true, true},
                              .meaning = "the vertical field of view, in degrees"};
inline const Key<float> kFdist{
    .name = "fdist",
    .defaultValue = 1,
    .allowed = {0, kMaxSceneCoordinate, true, false},
    .meaning = "the focus distance along the viewing direction (matters only with an aperture)"};
inline const Key<float> kAperture{
    .name = "aperture",
    .defaultValue = 0,
    .allowed = {0, kMaxSceneCoordinate},
    .meaning = "the lens radius; 0 is a pinhole (everything in focus)"};

// A surface of type "group", besides surfaceCommonKeys() (shape_registry.h).
inline const KeyDeclaration kChildren{
    "children",        {},         ValueType::Array,
    "surface objects", "required", "the surfaces of the group, placed by the group's transform"};

// Every "sampler" object, besides "type" and its type's keys (sampler_type.h).
inline const Key<int> kSamples{
    .name = "samples",
    .allowed = kSampleCount,
    .meaning =
        "samples per pixel; when the top level gives \"image_samples\" too, both must say "
        "the same number",
    .defaultText = "\"image_samples\", else 1"};

}  // namespace verity::scene_keys

namespace verity {

// The key lists of the objects above, for JsonNode::declare and the documents; a sampler's
// "type" (samplerTypes().typeKey()) and "samples".
const KeyList& sceneKeys();
const KeyList& cameraKeys();
const KeyList& groupKeys();
const KeyList& samplerCommonKeys();

}  // namespace verity
