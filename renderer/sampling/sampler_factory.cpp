#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "params/json_node.h"
#include "sampling/sampler.h"
#include "sampling/sampler_registry.h"

namespace verity {

void requireIndependentSamples(const Sampler& sampler, const std::string& file,
                               const std::string& use) {
  if (sampler.samplesAreIndependent()) return;
  throw VerityError(file, "sampler.type",
                    use +
                        " estimate a variance from the spread of each pixel's samples, which "
                        "only independent samples allow; this sampler correlates them (use the "
                        "independent sampler, or compare renders made with different seeds)");
}

std::unique_ptr<Sampler> makeSampler(const JsonNode* node) {
  if (!node) return samplerTypes().front().build(nullptr);
  if (!node->isObject()) node->fail("expected a sampler object");
  const std::string type = node->has({"type"}) ? node->type() : samplerTypes().front().name;
  const SamplerType* entry = findSamplerType(type);
  if (!entry)
    (*node)[{"type"}].fail("unsupported sampler type \"" + type + "\" (expected one of " +
                           samplerTypeList() + ")");
  return entry->build(node);
}

std::unique_ptr<Sampler> makeSampler(const std::string& name, const std::string& option) {
  std::string spelling = name;
  std::transform(spelling.begin(), spelling.end(), spelling.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  const SamplerType* entry = findSamplerType(spelling);
  if (!entry)
    throw VerityError(
        "", option, "unknown sampler \"" + name + "\" (expected one of " + samplerTypeList() + ")");
  return entry->build(nullptr);
}

}  // namespace verity
