#include "integrators/integrator_settings.h"

#include <algorithm>

#include "integrators/ambient_occlusion.h"
#include "integrators/light_tracer.h"
#include "integrators/normals.h"
#include "integrators/path_tracer.h"

namespace verity {

std::string canonicalIntegratorType(const std::string& type) {
  std::string t = type;
  std::replace(t.begin(), t.end(), ' ', '_');
  static const char* known[] = {"normals",         "ao",   "path_tracer_mats", "path_tracer_nee",
                                "path_tracer_mis", "bdpt", "light_tracer"};
  for (const char* k : known)
    if (t == k) return k;
  if (t == "ambient_occlusion") return "ao";
  return "";
}

IntegratorSettings parseIntegratorSettings(const JsonNode* node) {
  IntegratorSettings s;
  if (!node) return s;
  if (!node->isObject()) node->fail("expected an integrator object with a \"type\"");
  const std::string given = node->type();
  s.type = canonicalIntegratorType(given);
  if (s.type.empty())
    (*node)[{"type"}].fail("unknown integrator type \"" + given +
                           "\" (expected normals, ao, path_tracer_mats, path_tracer_nee, "
                           "path_tracer_mis, bdpt or light_tracer)");
  if (s.type.rfind("path_tracer", 0) == 0 || s.type == "bdpt" || s.type == "light_tracer")
    s.maxBounces = node->getInt({"max_bounces", "max bounces"}, s.maxBounces, 0, kMaxBouncesLimit);
  if (s.type == "path_tracer_mis" || s.type == "bdpt")
    s.misPower = node->getFloat({"power"}, s.misPower, Range{0, 16, true, false});
  if (s.type == "ao") s.aoDistance = node->getFloat({"distance"}, s.aoDistance, Range::positive());
  node->rejectUnknownKeys();
  return s;
}

std::unique_ptr<Integrator> makeIntegrator(const IntegratorSettings& s) {
  if (s.type == "normals") return std::make_unique<NormalsIntegrator>();
  if (s.type == "ao") return std::make_unique<AmbientOcclusion>(s.aoDistance);
  if (s.type == "path_tracer_mats")
    return std::make_unique<PathTracer>(PathTracer::Strategy::Materials, s.maxBounces, 1);
  if (s.type == "path_tracer_nee")
    return std::make_unique<PathTracer>(PathTracer::Strategy::NextEvent, s.maxBounces, 1);
  if (s.type == "bdpt")
    return std::make_unique<Bdpt>(s.maxBounces, s.misPower, s.bdptDroppedStrategy);
  if (s.type == "light_tracer") return std::make_unique<LightTracer>(s.maxBounces);
  return std::make_unique<PathTracer>(PathTracer::Strategy::Mis, s.maxBounces, s.misPower);
}

}  // namespace verity
