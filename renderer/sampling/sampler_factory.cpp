#include "sampling/independent_sampler.h"
#include "sampling/stratified_sampler.h"
#include "scene/json_node.h"

namespace verity {

std::unique_ptr<Sampler> makeSampler(const JsonNode* node) {
  if (!node) return std::make_unique<IndependentSampler>();
  if (!node->isObject()) node->fail("expected a sampler object");
  const std::string type = node->has({"type"}) ? node->type() : "independent";
  if (type == "independent") return std::make_unique<IndependentSampler>();
  if (type == "stratified") return std::make_unique<StratifiedSampler>();
  (*node)[{"type"}].fail("unsupported sampler type \"" + type +
                         "\" (expected independent or stratified)");
}

}  // namespace verity
