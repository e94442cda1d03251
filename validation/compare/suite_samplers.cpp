#include "validation/compare/suite_samplers.h"

#include "sampling/sampler.h"

namespace verity::validation {

const char* suiteSampler(int scene, int integrator) {
  return kSuiteSamplers[size_t(scene + integrator) % kSuiteSamplers.size()];
}

void useSampler(SceneFile& file, const std::string& type, int spp) {
  file.sampler = makeSampler(type, "sampler");
  file.sampler->setSamplesPerPixel(spp);
}

}  // namespace verity::validation
