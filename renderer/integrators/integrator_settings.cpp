#include "integrators/integrator_settings.h"

#include <limits>
#include <stdexcept>

#include "integrators/integrator_registry.h"

namespace verity {

const IntegratorType& defaultIntegratorType() {
  static const IntegratorType& type = *findIntegratorType("path_tracer_mats");
  return type;
}

const IntegratorType& integratorTypeNamed(const std::string& name, const std::string& option) {
  const IntegratorType* type = findIntegratorType(name);
  if (!type)
    throw VerityError(
        "", option,
        "unknown integrator type \"" + name + "\" (expected " + integratorTypeList() + ")");
  return *type;
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
  if (overrides.rrDepth > 0) {
    if (!settings.type->hasRussianRoulette)
      throw VerityError("", "--rr-depth",
                        "the integrator \"" + settings.type->name + "\" has no Russian roulette");
    settings.rrDepth = overrides.rrDepth;
  }
  return settings;
}

IntegratorSettings parseIntegratorSettings(const JsonNode* node) {
  IntegratorSettings s;
  if (!node) return s;
  if (!node->isObject()) node->fail("expected an integrator object with a \"type\"");
  const std::string given = node->type();
  const IntegratorType* type = findIntegratorType(given);
  if (!type)
    (*node)[{"type"}].fail("unknown integrator type \"" + given + "\" (expected " +
                           integratorTypeList() + ")");
  s.type = type;
  node->declare({"integrator " + type->name, {&integratorCommonKeys(), &type->keys}});
  // Each key is read only by the types that declare it: another type's key is unknown.
  if (declaresKey(*type, "max_bounces"))
    s.maxBounces = node->getInt({"max_bounces", "max bounces"}, s.maxBounces, 0, kMaxBouncesLimit);
  if (declaresKey(*type, "rr_depth"))
    s.rrDepth = node->getInt({"rr_depth"}, s.rrDepth, 1, std::numeric_limits<int>::max());
  if (declaresKey(*type, "power"))
    s.misPower = node->getFloat({"power"}, s.misPower, Range{0, 16, true, false});
  if (declaresKey(*type, "distance"))
    s.aoDistance = node->getFloat({"distance"}, s.aoDistance, Range::positive());
  node->rejectUnknownKeys();
  return s;
}

std::unique_ptr<Integrator> makeIntegrator(const IntegratorSettings& s) {
  if (!s.type) throw std::logic_error("integrator settings without a type");
  return s.type->make(s);
}

}  // namespace verity
