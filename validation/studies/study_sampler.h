// The samplers a study or bench compares, named as in the sampler registry
// (sampling/sampler_registry.h): each a prototype that the renders clone and seed.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "loader/scene_loader.h"

namespace verity::studies {

struct StudySampler {
  std::string type;  // the registry's canonical name
  std::unique_ptr<Sampler> prototype;
};

// The registry name of `sampler`'s type.
std::string samplerTypeName(const Sampler& sampler);

// For each name (any spelling the registry accepts, any case): the scene's own sampler when it
// is of that type (its keys kept), else that type with its keys at their defaults; no names:
// the scene's own. Each keeps the scene's sample count. An unknown or repeated name is an
// error naming `option` and listing the registry's names.
std::vector<StudySampler> prepareSamplers(const SceneFile& file,
                                          const std::vector<std::string>& names,
                                          const std::string& option);

// Why a study leaves out the variance estimated from a pixel's own samples (rel_variance) for
// a sampler whose samples are not independent.
inline constexpr const char* kCorrelatedSamplesNote =
    "the sampler correlates a pixel's samples, whose spread would overstate the variance of "
    "their mean; relMSE against the reference is unaffected";

// Whether the registry type `type` gives a pixel independent samples (Sampler::
// samplesAreIndependent), so that their spread estimates the variance of their mean; null
// when the registry has no such type.
std::optional<bool> samplerSamplesAreIndependent(const std::string& type);

}  // namespace verity::studies
