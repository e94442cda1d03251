// Every sampler type of the scene format, from one table: the factory (makeSampler) looks
// types up here, and help text and the "unsupported sampler type" error read their names
// from here.
#pragma once

#include <string>
#include <vector>

#include "sampling/sampler_type.h"

namespace verity {

// In the order of the table in sampler_registry.cpp; the first is the default type.
const std::vector<SamplerType>& samplerTypes();
// The type with this name or alias (lower case, as JsonNode::type() gives it); null if none.
const SamplerType* findSamplerType(const std::string& spelling);
// "independent, stratified, ...": the canonical names, for error messages.
std::string samplerTypeList();
// One line per type: its names (aliases in parentheses) and its description.
std::string samplerTypeHelp();

}  // namespace verity
