#include "sampling/sampler_registry.h"

#include "sampling/halton_sampler.h"
#include "sampling/independent_sampler.h"
#include "sampling/sobol_sampler.h"
#include "sampling/stratified_sampler.h"

namespace verity {

// An explicit list rather than self-registering static objects: verity_renderer is a static
// library, and the linker drops an object file that nothing references, together with the
// registrar it holds. A function-local table is built on first use, in a fixed order. A new
// type adds its entry function here.
const std::vector<SamplerType>& samplerTypes() {
  static const std::vector<SamplerType> types = {
      independentSamplerType(),
      stratifiedSamplerType(),
      haltonSamplerType(),
      sobolSamplerType(),
  };
  return types;
}

const SamplerType* findSamplerType(const std::string& spelling) {
  for (const SamplerType& t : samplerTypes()) {
    if (t.name == spelling) return &t;
    for (const std::string& alias : t.aliases)
      if (alias == spelling) return &t;
  }
  return nullptr;
}

std::string samplerTypeList() {
  std::string list;
  for (const SamplerType& t : samplerTypes()) list += (list.empty() ? "" : ", ") + t.name;
  return list;
}

std::string samplerTypeHelp() {
  std::string help;
  for (const SamplerType& t : samplerTypes()) {
    std::string names = t.name;
    if (!t.aliases.empty()) {
      names += " (";
      for (size_t i = 0; i < t.aliases.size(); ++i) names += (i ? ", " : "") + t.aliases[i];
      names += ")";
    }
    help += "  " + names + ": " + t.description + "\n";
  }
  return help;
}

}  // namespace verity
