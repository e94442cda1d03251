#include "loader/scene_keys.h"

namespace verity {

const KeyList& sceneKeys() {
  static const KeyList keys = {
      {"camera", {}, ValueType::Object, "", "required", "the camera (see Camera)"},
      {"integrator",
       {},
       ValueType::Object,
       "",
       "{\"type\": \"path_tracer_mats\"}",
       "the integrator and its settings (see Integrators)"},
      {"sampler",
       {},
       ValueType::Object,
       "",
       "{\"type\": \"independent\"}",
       "the sample generator and the sample count (see Samplers)"},
      {"image_samples",
       {},
       ValueType::Integer,
       "[1, 16777216]",
       "1",
       "samples per pixel (DIRT's spelling); \"sampler\".\"samples\" may say it too, but only "
       "the same number"},
      {"background",
       {},
       ValueType::Any,
       "a number, [r, g, b] or a background object",
       "0 (black)",
       "radiance arriving from infinity where a ray escapes (see Backgrounds)"},
      {"accelerator",
       {},
       ValueType::Any,
       "",
       "none",
       "DIRT's choice of acceleration structure: accepted and ignored (Embree serves all)"},
      {"materials",
       {},
       ValueType::Array,
       "material objects, each with a unique \"name\"",
       "[]",
       "the named materials, in order: a blend may name only materials listed before it"},
      {"surfaces",
       {},
       ValueType::Array,
       "surface objects",
       "[]",
       "the shapes and groups of the scene (see Surfaces)"}};
  return keys;
}

const KeyList& cameraKeys() {
  static const KeyList keys = {
      {"transform",
       {},
       ValueType::Transform,
       "a similarity (no shear or non-uniform scale)",
       "identity",
       "places the camera: it looks down its local -z axis with +y up; a look-at is usual"},
      {"resolution",
       {},
       ValueType::Array,
       "[width, height], integers in [1, 32768], at most 8192 × 8192 pixels in all",
       "[512, 512]",
       "the image size in pixels"},
      {"vfov", {}, ValueType::Number, "(0, 180)", "90", "the vertical field of view, in degrees"},
      {"fdist",
       {},
       ValueType::Number,
       "(0, 1e15]",
       "1",
       "the focus distance along the viewing direction (matters only with an aperture)"},
      {"aperture",
       {},
       ValueType::Number,
       "[0, 1e15]",
       "0",
       "the lens radius; 0 is a pinhole (everything in focus)"}};
  return keys;
}

const KeyList& groupKeys() {
  static const KeyList keys = {{"children",
                                {},
                                ValueType::Array,
                                "surface objects",
                                "required",
                                "the surfaces of the group, placed by the group's transform"}};
  return keys;
}

const KeyList& samplerCommonKeys() {
  static const KeyList keys = {
      {"type",
       {},
       ValueType::String,
       "a sampler type's name (any letter case)",
       "\"independent\"",
       "the sampler type"},
      {"samples",
       {},
       ValueType::Integer,
       "[1, 16777216]",
       "\"image_samples\", else 1",
       "samples per pixel; when the top level gives \"image_samples\" too, both must say the "
       "same number"}};
  return keys;
}

}  // namespace verity
