#include "integrators/integrator_registry.h"

#include <fmt/format.h>

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
                                      RussianRoulette(s.rrDepth));
}

// The keys the integrators share. Their defaults are IntegratorSettings' own (named
// constants: the table cannot make settings, whose default type is one of its entries).
KeyDeclaration maxBouncesKey() {
  return {"max_bounces",
          {"max bounces"},
          ValueType::Integer,
          fmt::format("[0, {}]", kMaxBouncesLimit),
          std::to_string(kDefaultMaxBounces),
          "the most scattering events on a path: 0 shows only emitters seen directly, 1 adds "
          "direct lighting"};
}

KeyDeclaration rrDepthKey() {
  return {"rr_depth",
          {},
          ValueType::Integer,
          ">= 1",
          std::to_string(kDefaultRouletteDepth),
          "the non-specular scattering event after which Russian roulette first decides "
          "whether a path goes on (1: after the first; specular events, at mirrors and "
          "smooth glass, are not counted); one more than max_bounces turns the roulette off"};
}

KeyDeclaration misPowerKey(const std::string& what) {
  return {"power",
          {},
          ValueType::Number,
          "(0, 16]",
          "1",
          "the exponent of the power heuristic that weights " + what +
              ": 1 is the balance heuristic, 2 Veach's usual power heuristic"};
}

KeyDeclaration aoDistanceKey() {
  return {"distance",
          {},
          ValueType::Number,
          "> 0",
          "infinite",
          "the occlusion radius: a point is occluded in a direction when a surface lies closer "
          "than this"};
}

// One explicit table rather than self-registering objects: the renderer is a static library,
// and the linker drops an object file nothing references, registration and all.
std::vector<IntegratorType> makeTable() {
  std::vector<IntegratorType> t;
  t.push_back({.name = "normals",
               .description = "shading normals as colours (a debugging view)",
               .make = [](const IntegratorSettings&) -> std::unique_ptr<Integrator> {
                 return std::make_unique<NormalsIntegrator>();
               }});
  t.push_back({.name = "ao",
               .aliases = {"ambient_occlusion"},
               .description = "ambient occlusion within \"distance\"",
               .keys = {aoDistanceKey()},
               .make = [](const IntegratorSettings& s) -> std::unique_ptr<Integrator> {
                 return std::make_unique<AmbientOcclusion>(s.aoDistance);
               }});
  t.push_back({.name = "path_tracer_mats",
               .description = "path tracing by material sampling only (no shadow rays)",
               .strategies = "emission found by material sampling alone: rays that hit an "
                             "emitter or escape to the background; no shadow rays",
               .estimatesRadiance = true,
               .keys = {maxBouncesKey(), rrDepthKey()},
               .hasRussianRoulette = true,
               .make = makePathTracer<PathTracer::Strategy::Materials>});
  t.push_back({.name = "path_tracer_nee",
               .description = "path tracing with next-event estimation",
               .strategies = "next-event estimation (a shadow ray to a sampled point on a "
                             "light or direction of the background) at non-delta surfaces; "
                             "emission hit by material sampling only when seen directly or "
                             "after a delta bounce",
               .estimatesRadiance = true,
               .keys = {maxBouncesKey(), rrDepthKey()},
               .hasRussianRoulette = true,
               .make = makePathTracer<PathTracer::Strategy::NextEvent>});
  t.push_back({.name = "path_tracer_mis",
               .description = "path tracing, material and light samples combined by MIS",
               .strategies = "material sampling and next-event estimation at non-delta "
                             "surfaces, combined by multiple importance sampling (balance "
                             "heuristic, or power heuristic with \"power\")",
               .estimatesRadiance = true,
               .keys = {maxBouncesKey(), rrDepthKey(), misPowerKey("material and light samples")},
               .hasRussianRoulette = true,
               .make = makePathTracer<PathTracer::Strategy::Mis>});
  t.push_back({.name = "bdpt",
               .description = "bidirectional path tracing, MIS over every strategy (s, t)",
               .strategies = "every connection (s, t) of a light subpath of s vertices and a "
                             "camera subpath of t vertices, combined by multiple importance "
                             "sampling; light subpaths connected to the lens (t = 1) are "
                             "splatted",
               .estimatesRadiance = true,
               .keys = {maxBouncesKey(), rrDepthKey(), misPowerKey("the strategies (s, t)")},
               .hasRussianRoulette = true,
               .hasStrategies = true,
               .make = [](const IntegratorSettings& s) -> std::unique_ptr<Integrator> {
                 return std::make_unique<Bdpt>(s.maxBounces, s.misPower, RussianRoulette(s.rrDepth),
                                               s.bdptDroppedStrategy);
               }});
  t.push_back({.name = "light_tracer",
               .description = "light tracing: light subpaths splatted through the lens",
               .strategies = "light subpaths connected to the lens (t = 1) and splatted: "
                             "emitters and non-delta surfaces seen directly, and the background "
                             "seen directly; nothing the camera sees only in a mirror or through "
                             "smooth glass",
               .estimatesRadiance = true,
               .keys = {maxBouncesKey(), rrDepthKey()},
               .hasRussianRoulette = true,
               .splatsOnly = true,
               .make = [](const IntegratorSettings& s) -> std::unique_ptr<Integrator> {
                 return std::make_unique<LightTracer>(s.maxBounces, RussianRoulette(s.rrDepth));
               }});
  for (IntegratorType& type : t) type.readsMaxBounces = declaresKey(type, "max_bounces");
  return t;
}

}  // namespace

const std::vector<IntegratorType>& integratorTypes() {
  static const std::vector<IntegratorType> table = makeTable();
  return table;
}

const KeyList& integratorCommonKeys() {
  static const KeyList keys = {{"type",
                                {},
                                ValueType::String,
                                "a type's name or other spelling (any letter case; spaces read "
                                "as _)",
                                "\"" + defaultIntegratorType().name + "\"",
                                "the integrator type"}};
  return keys;
}

bool declaresKey(const IntegratorType& type, const std::string& name) {
  return std::any_of(type.keys.begin(), type.keys.end(),
                     [&](const KeyDeclaration& k) { return k.name == name; });
}

const IntegratorType* findIntegratorType(const std::string& name) {
  std::string spelled = name;
  std::replace(spelled.begin(), spelled.end(), ' ', '_');
  for (const IntegratorType& t : integratorTypes())
    if (t.name == spelled ||
        std::find(t.aliases.begin(), t.aliases.end(), spelled) != t.aliases.end())
      return &t;
  return nullptr;
}

std::string integratorTypeList() {
  const auto& types = integratorTypes();
  std::string list;
  for (size_t i = 0; i < types.size(); ++i)
    list += (i == 0 ? "" : i + 1 == types.size() ? " or " : ", ") + types[i].name;
  return list;
}

std::vector<std::string> radianceIntegrators() {
  std::vector<std::string> names;
  for (const IntegratorType& t : integratorTypes())
    if (t.estimatesRadiance) names.push_back(t.name);
  return names;
}

}  // namespace verity
