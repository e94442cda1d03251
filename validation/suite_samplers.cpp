#include "validation/suite_samplers.h"

#include <stdexcept>

#include "sampling/sampler.h"
#include "sampling/sampler_registry.h"

namespace verity::validation {

const char* suiteSampler(int scene, int integrator) {
  return kSuiteSamplers[size_t(scene + integrator) % kSuiteSamplers.size()];
}

void useSampler(SceneFile& file, const std::string& type, int spp) {
  const SamplerType* entry = findSamplerType(type);
  if (!entry) throw std::invalid_argument("no sampler type \"" + type + "\"");
  file.sampler = entry->build(nullptr);
  file.sampler->setSamplesPerPixel(spp);
}

}  // namespace verity::validation
