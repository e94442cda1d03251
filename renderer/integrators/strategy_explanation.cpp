#include "integrators/strategy_explanation.h"

#include <fmt/format.h>

namespace verity {

std::string explainStrategies(const IntegratorType& type, const SceneSummary& scene) {
  if (!type.estimatesRadiance)
    return fmt::format("strategies: none; {} transports no light: {}\n", type.name,
                       type.description);
  if (!scene.hasEmitters())
    return "strategies: none can carry light; radiance integrators output black without "
           "tracing a ray\n";
  std::string s = fmt::format("strategies: {}\n", type.strategies);
  // Only material sampling reaches emitters without a non-delta surface to connect at.
  if (!scene.hasNonDeltaLobes && type.name != "path_tracer_mats")
    s += type.splatsOnly
             ? "note: no non-delta surface: only emitters and the background seen directly "
               "reach the image\n"
             : "note: no non-delta surface: next-event estimation and connections never run\n";
  if (type.splatsOnly && scene.hasDeltaLobes)
    s += "note: the scene has delta (specular) lobes: what the camera sees only through them "
         "stays black\n";
  return s;
}

}  // namespace verity
