#include "integrators/integrator_settings.h"

#include <limits>
#include <stdexcept>

#include "integrators/integrator_registry.h"

namespace verity {

IntegratorSettings overrideIntegrator(IntegratorSettings settings, const std::string& type,
                                      int maxBounces, const std::string& option) {
  if (!type.empty()) {
    const IntegratorType* t = findIntegratorType(type);
    if (!t)
      throw VerityError(
          "", option,
          "unknown integrator type \"" + type + "\" (expected " + integratorTypeList() + ")");
    settings.type = t->name;
  }
  if (maxBounces >= 0) settings.maxBounces = maxBounces;
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
  s.type = type->name;
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
  const IntegratorType* type = findIntegratorType(s.type);
  // Settings come from parseIntegratorSettings or a command's check of the name.
  if (!type) throw std::logic_error("no integrator type \"" + s.type + "\"");
  return type->make(s);
}

}  // namespace verity
