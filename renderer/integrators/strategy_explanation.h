// What `verity render --explain` says about how the chosen integrator finds the scene's
// light: its strategies (from the integrator table), and what the scene leaves them to do.
#pragma once

#include <string>

#include "integrators/integrator_registry.h"
#include "scene/scene.h"

namespace verity {

// One or more lines, each starting "strategies: " or "note: ".
std::string explainStrategies(const IntegratorType& type, const SceneSummary& scene);

}  // namespace verity
