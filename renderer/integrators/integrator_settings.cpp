#include "integrators/integrator_settings.h"

#include <stdexcept>

#include "integrators/integrator_registry.h"

namespace verity {

IntegratorSettings overrideIntegrator(IntegratorSettings settings, const std::string& type,
                                      int maxBounces, const std::string& option) {
  if (!type.empty()) {
    settings.type = integratorTypes().get(type, option).name;
  }
  if (maxBounces >= 0) settings.maxBounces = maxBounces;
  return settings;
}

IntegratorSettings parseIntegratorSettings(const JsonNode* node) {
  IntegratorSettings s;
  if (!node) return s;
  if (!node->isObject()) node->fail("expected an integrator object with a \"type\"");
  const IntegratorType* type = &integratorTypes().get((*node)[{"type"}]);
  s.type = type->name;
  node->declare({"integrator " + type->name, {&integratorCommonKeys(), &type->keys}});
  // Each key is read only by the types that declare it: another type's key is unknown.
  using namespace integrator_keys;
  if (declaresKey(*type, kMaxBounces.name)) s.maxBounces = node->get(kMaxBounces);
  if (declaresKey(*type, kRrDepth.name)) s.rrDepth = node->get(kRrDepth);
  if (declaresKey(*type, kMisPower.name)) s.misPower = node->get(kMisPower);
  if (declaresKey(*type, kAoDistance.name)) s.aoDistance = node->get(kAoDistance);
  node->rejectUnknownKeys();
  return s;
}

std::unique_ptr<Integrator> makeIntegrator(const IntegratorSettings& s) {
  const IntegratorType* type = findIntegratorType(s.type);
  // Settings come from parseIntegratorSettings or a command's check of the name.
  if (!type) throw std::logic_error("no integrator type \"" + s.type + "\"");
  return type->make(s);
}

}  // namespace verity
