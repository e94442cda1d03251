// One entry of the sampler registry (sampler_registry.h): a type's canonical name in the
// scene format, its other spellings, a one-line description for help and errors, the keys
// its "sampler" object takes, and the function that builds the sampler from that object.
// Each sampler's own file defines its entry (independentSamplerType() in
// independent_sampler.cpp, ...), next to the class it builds.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "params/key_declaration.h"

namespace verity {

class JsonNode;
class Sampler;

struct SamplerType {
  // Reads the type's keys from `node`, the scene's "sampler" object, or null when the scene
  // gives none (every key at its default). Unknown keys are rejected by the scene loader.
  using Build = std::unique_ptr<Sampler> (*)(const JsonNode* node);
  std::string name;                  // canonical; looked up by the rule of params/registry.h
  std::vector<std::string> aliases;  // other spellings of the same type
  std::string description;           // one line: what it is
  // The type's own keys, besides samplerCommonKeys() (scene_keys.h: "type" and the sample
  // count "samples", which the scene loader reads for every type). Build may read only these.
  KeyList keys;
  Build build;
};

}  // namespace verity
