// Every sampler type of the scene format, from one table: the factory (makeSampler) looks
// types up here, and help text and the "unknown sampler type" error read their names
// from here.
#pragma once

#include <string>
#include <vector>

#include "params/registry.h"
#include "sampling/sampler_type.h"

namespace verity {

// In the order of the table in sampler_registry.cpp; the first is the default type.
const Registry<SamplerType>& samplerTypes();
// The table's lookup and list, as the commands and studies outside the renderer spell them.
inline const SamplerType* findSamplerType(std::string_view spelling) {
  return samplerTypes().find(spelling);
}
inline std::string samplerTypeList() {
  return samplerTypes().names();
}

}  // namespace verity
