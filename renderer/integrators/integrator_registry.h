// Every integrator type the renderer knows, in one table: its name and other spellings, what
// it computes, the keys it reads (docs/scene-format.md prints them), and how it is made. The
// scene loader, the commands' help and errors, and the suites that must cover every estimator
// all read this table.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "integrators/integrator.h"
#include "params/key_declaration.h"

namespace verity {

struct IntegratorSettings;

struct IntegratorType {
  std::string name;                  // canonical, as records and manifests spell it
  std::vector<std::string> aliases;  // other accepted spellings (spaces read as '_')
  std::string description;
  // How it finds light, for --explain: the strategies it samples paths with, and the light it
  // cannot find. Empty for the debugging views, which do not transport light.
  std::string strategies;
  // An estimator of radiance (not a debugging view): the agreement, invariance and
  // stability suites must cover it.
  bool estimatesRadiance = false;
  // The keys its "integrator" object takes besides integratorCommonKeys() ("type"); the
  // settings reader reads exactly these (integrator_settings.cpp).
  KeyList keys;
  // Declares "max_bounces" (set from `keys`): it can split its image by path length.
  bool readsMaxBounces = false;
  // Ends paths by Russian roulette and so reads "rr_depth" (--rr-depth applies).
  bool hasRussianRoulette = false;
  bool hasStrategies = false;  // per-(s, t) strategy images (BDPT)
  // Sees only the pixels a light subpath reaches through the lens (t = 1 splats).
  bool splatsOnly = false;
  std::unique_ptr<Integrator> (*make)(const IntegratorSettings&) = nullptr;
};

const std::vector<IntegratorType>& integratorTypes();
// The keys every integrator object takes: "type".
const KeyList& integratorCommonKeys();
// Whether `type` declares the key named `name` (its canonical spelling).
bool declaresKey(const IntegratorType& type, const std::string& name);
// The type `name` (any accepted spelling), or nullptr.
const IntegratorType* findIntegratorType(const std::string& name);
// The canonical names, for help and errors: "normals, ao, ... or light_tracer".
std::string integratorTypeList();
// The canonical names of the radiance estimators, in table order.
std::vector<std::string> radianceIntegrators();

}  // namespace verity
