#include "integrators/integrator_registry.h"

#include <algorithm>

#include "integrators/ambient_occlusion.h"
#include "integrators/bdpt.h"
#include "integrators/integrator_settings.h"
#include "integrators/light_tracer.h"
#include "integrators/normals.h"
#include "integrators/path_tracer.h"

namespace verity {

namespace {

template <PathTracer::Strategy strategy>
std::unique_ptr<Integrator> makePathTracer(const IntegratorSettings& s) {
  return std::make_unique<PathTracer>(strategy, s.maxBounces,
                                      strategy == PathTracer::Strategy::Mis ? s.misPower : 1,
                                      makeRoulette(s));
}

// "power" as the type lists it: what its heuristic weights.
Key<float> misPowerKey(const std::string& what) {
  return integrator_keys::kMisPower.described(
      "the exponent of the power heuristic that weights " + what +
      ": 1 is the balance heuristic, 2 Veach's usual power heuristic");
}

// One explicit table rather than self-registering objects: the renderer is a static library,
// and the linker drops an object file nothing references, registration and all.
std::vector<IntegratorType> makeTable() {
  using namespace integrator_keys;
  std::vector<IntegratorType> t;
  t.push_back({.name = "normals",
               .description = "shading normals as colours (a debugging view)",
               .make = [](const IntegratorSettings&) -> std::unique_ptr<Integrator> {
                 return std::make_unique<NormalsIntegrator>();
               }});
  t.push_back({.name = "ao",
               .aliases = {"ambient_occlusion"},
               .description = "ambient occlusion within \"distance\"",
               .keys = declarations(kAoDistance),
               .make = [](const IntegratorSettings& s) -> std::unique_ptr<Integrator> {
                 return std::make_unique<AmbientOcclusion>(s.aoDistance);
               }});
  t.push_back({.name = "path_tracer_mats",
               .description = "path tracing by material sampling only (no shadow rays)",
               .strategies = "emission found by material sampling alone: rays that hit an "
                             "emitter or escape to the background; no shadow rays",
               .estimatesRadiance = true,
               .keys = declarations(kMaxBounces),
               .hasRussianRoulette = true,
               .rouletteThreshold = kPathTracerRouletteThreshold,
               .make = makePathTracer<PathTracer::Strategy::Materials>});
  t.push_back({.name = "path_tracer_nee",
               .description = "path tracing with next-event estimation",
               .strategies = "next-event estimation (a shadow ray to a sampled point on a "
                             "light or direction of the background) at non-delta surfaces; "
                             "emission hit by material sampling only when seen directly or "
                             "after a delta bounce",
               .estimatesRadiance = true,
               .keys = declarations(kMaxBounces),
               .hasRussianRoulette = true,
               .rouletteThreshold = kPathTracerRouletteThreshold,
               .make = makePathTracer<PathTracer::Strategy::NextEvent>});
  t.push_back({.name = "path_tracer_mis",
               .description = "path tracing, material and light samples combined by MIS",
               .strategies = "material sampling and next-event estimation at non-delta "
                             "surfaces, combined by multiple importance sampling (balance "
                             "heuristic, or power heuristic with \"power\")",
               .estimatesRadiance = true,
               .keys = declarations(kMaxBounces, misPowerKey("material and light samples")),
               .hasRussianRoulette = true,
               .rouletteThreshold = kPathTracerRouletteThreshold,
               .make = makePathTracer<PathTracer::Strategy::Mis>});
  t.push_back({.name = "bdpt",
               .description = "bidirectional path tracing, MIS over every strategy (s, t)",
               .strategies = "every connection (s, t) of a light subpath of s vertices and a "
                             "camera subpath of t vertices, combined by multiple importance "
                             "sampling; light subpaths connected to the lens (t = 1) are "
                             "splatted",
               .estimatesRadiance = true,
               .keys = declarations(kMaxBounces, misPowerKey("the strategies (s, t)")),
               .hasRussianRoulette = true,
               .rouletteThreshold = kBdptRouletteThreshold,
               .hasStrategies = true,
               .make = [](const IntegratorSettings& s) -> std::unique_ptr<Integrator> {
                 return std::make_unique<Bdpt>(s.maxBounces, s.misPower, makeRoulette(s),
                                               s.bdptDroppedStrategy);
               }});
  t.push_back({.name = "light_tracer",
               .description = "light tracing: light subpaths splatted through the lens",
               .strategies = "light subpaths connected to the lens (t = 1) and splatted: "
                             "emitters and non-delta surfaces seen directly, and the background "
                             "seen directly; nothing the camera sees only in a mirror or through "
                             "smooth glass",
               .estimatesRadiance = true,
               .keys = declarations(kMaxBounces),
               .hasRussianRoulette = true,
               .rouletteThreshold = kLightTracerRouletteThreshold,
               .splatsOnly = true,
               .make = [](const IntegratorSettings& s) -> std::unique_ptr<Integrator> {
                 return std::make_unique<LightTracer>(s.maxBounces, makeRoulette(s));
               }});
  for (IntegratorType& type : t) {
    if (type.hasRussianRoulette) {
      const KeyList roulette =
          declarations(integrator_keys::kRrDepth,
                       integrator_keys::kRrThreshold.withDefault(type.rouletteThreshold));
      type.keys.insert(type.keys.begin() + (type.keys.empty() ? 0 : 1), roulette.begin(),
                       roulette.end());
    }
    type.readsMaxBounces = declaresKey(type, "max_bounces");
  }
  return t;
}

}  // namespace

const Registry<IntegratorType>& integratorTypes() {
  static const Registry<IntegratorType> table("integrator type", makeTable());
  return table;
}

const KeyList& integratorCommonKeys() {
  static const KeyList keys = {
      integratorTypes().typeKey("\"" + defaultIntegratorType().name + "\"")};
  return keys;
}

bool declaresKey(const IntegratorType& type, const std::string& name) {
  return std::any_of(type.keys.begin(), type.keys.end(),
                     [&](const KeyDeclaration& k) { return k.name == name; });
}

std::vector<std::string> radianceIntegrators() {
  std::vector<std::string> names;
  for (const IntegratorType& t : integratorTypes())
    if (t.estimatesRadiance) names.push_back(t.name);
  return names;
}

}  // namespace verity
