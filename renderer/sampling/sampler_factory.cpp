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
  if (!node->has({"type"})) return samplerTypes().front().build(node);
  return samplerTypes().get((*node)[{"type"}]).build(node);
}

std::unique_ptr<Sampler> makeSampler(const std::string& name, const std::string& option) {
  return samplerTypes().get(name, option).build(nullptr);
}

}  // namespace verity
