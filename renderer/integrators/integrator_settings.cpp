#include "integrators/integrator_settings.h"

#include <stdexcept>

#include "integrators/integrator_registry.h"

namespace verity {

const IntegratorType& defaultIntegratorType() {
  static const IntegratorType& type = integratorTypes().get("path_tracer_mats", "");
  return type;
}

const IntegratorType& integratorTypeNamed(const std::string& name, const std::string& option) {
  return integratorTypes().get(name, option);
}

IntegratorOverrides integratorOverrides(const std::string& type, int maxBounces) {
  IntegratorOverrides overrides;
  if (!type.empty()) overrides.type = &integratorTypeNamed(type, "--integrator");
  overrides.maxBounces = maxBounces;
  return overrides;
}

IntegratorSettings overrideIntegrator(IntegratorSettings settings,
                                      const IntegratorOverrides& overrides) {
  if (overrides.type) settings.type = overrides.type;
  if (overrides.maxBounces >= 0) settings.maxBounces = overrides.maxBounces;
  const auto requireRoulette = [&](const char* option) {
    if (!settings.type->hasRussianRoulette)
      throw VerityError("", option,
                        "the integrator \"" + settings.type->name + "\" has no Russian roulette");
  };
  if (overrides.rrDepth > 0) {
    requireRoulette("--rr-depth");
    settings.rrDepth = overrides.rrDepth;
  }
  if (overrides.rrThreshold > 0) {
    requireRoulette("--rr-threshold");
    settings.rrThreshold = overrides.rrThreshold;
  }
  return settings;
}

IntegratorSettings parseIntegratorSettings(const JsonNode* node) {
  IntegratorSettings s;
  if (!node) return s;
  if (!node->isObject()) node->fail("expected an integrator object with a \"type\"");
  const IntegratorType& type = integratorTypes().get((*node)[{"type"}]);
  s.type = &type;
  node->declare({"integrator " + type.name, {&integratorCommonKeys(), &type.keys}});
  // Each key is read only by the types that declare it: another type's key is unknown.
  using namespace integrator_keys;
  if (declaresKey(type, kMaxBounces.name)) s.maxBounces = node->get(kMaxBounces);
  if (declaresKey(type, kRrDepth.name)) s.rrDepth = node->get(kRrDepth);
  if (declaresKey(type, kRrThreshold.name) && node->find(kRrThreshold))
    s.rrThreshold = node->get(kRrThreshold);
  if (declaresKey(type, kMisPower.name)) s.misPower = node->get(kMisPower);
  if (declaresKey(type, kAoDistance.name)) s.aoDistance = node->get(kAoDistance);
  node->rejectUnknownKeys();
  return s;
}

RussianRoulette makeRoulette(const IntegratorSettings& s) {
  return RussianRoulette(s.rrDepth, s.rrThreshold.value_or(s.type->rouletteThreshold));
}

std::unique_ptr<Integrator> makeIntegrator(const IntegratorSettings& s) {
  if (!s.type) throw std::logic_error("integrator settings without a type");
  return s.type->make(s);
}

}  // namespace verity
