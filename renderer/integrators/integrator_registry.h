// Every integrator type the renderer knows, in one table: its name and other spellings, what
// it computes, the keys it reads (docs/scene-format.md prints them), and how it is made. The
// scene loader, the commands' help and errors, and the suites that must cover every estimator
// all read this table.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "integrators/integrator.h"
#include "integrators/integrator_settings.h"
#include "params/key.h"
#include "params/key_declaration.h"
#include "params/registry.h"

namespace verity {

// The keys the integrators share, each declared once: the types' entries list them and
// parseIntegratorSettings reads them. Their defaults are IntegratorSettings' own (its named
// constants: default settings point into this table, which lists these keys).
namespace integrator_keys {
inline const Key<int> kMaxBounces{
    .name = "max_bounces",
    .aliases = {"max bounces"},
    .defaultValue = kDefaultMaxBounces,
    .allowed = {0, kMaxBouncesLimit},
    .meaning =
        "the most scattering events on a path: 0 shows only emitters seen directly, 1 "
        "adds direct lighting"};
inline const Key<int> kRrDepth{
    .name = "rr_depth",
    .defaultValue = kDefaultRouletteDepth,
    .allowed = {1, std::numeric_limits<int>::max()},
    .meaning =
        "the non-specular scattering event after which Russian roulette first decides "
        "whether a path goes on (1: after the first; specular events, at mirrors and "
        "smooth glass, are not counted); one more than max_bounces turns the roulette off"};
// Each type with roulette lists it with its own default (IntegratorType::rouletteThreshold).
inline const Key<float> kRrThreshold{
    .name = "rr_threshold",
    .allowed = {0, 1, true, false},
    .meaning =
        "the throughput below which Russian roulette may end a path: from rr_depth on, a path "
        "whose throughput t (its largest channel, refraction's η² divided out) is below it "
        "goes on with probability t / rr_threshold, at least 0.05"};
inline const Key<float> kMisPower{
    .name = "power",
    .defaultValue = kDefaultMisPower,
    .allowed = {0, 16, true, false},
    .meaning =
        "the exponent of the power heuristic (each type that reads it says what it "
        "weights)"};
inline const Key<float> kAoDistance{
    .name = "distance",
    .defaultValue = kInfinity,
    .allowed = Range::positive(),
    .meaning =
        "the occlusion radius: a point is occluded in a direction when a surface lies "
        "closer than this"};
}  // namespace integrator_keys

struct IntegratorType {
  std::string name;                  // canonical, as records and manifests spell it
  std::vector<std::string> aliases;  // other accepted spellings
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
  // Ends paths by Russian roulette and so reads "rr_depth" and "rr_threshold" (--rr-depth and
  // --rr-threshold apply); the table adds both keys to `keys`, after "max_bounces".
  bool hasRussianRoulette = false;
  // Its "rr_threshold" when the scene gives none.
  float rouletteThreshold = 1;
  bool hasStrategies = false;  // per-(s, t) strategy images (BDPT)
  // Sees only the pixels a light subpath reaches through the lens (t = 1 splats).
  bool splatsOnly = false;
  std::unique_ptr<Integrator> (*make)(const IntegratorSettings&) = nullptr;
};

const Registry<IntegratorType>& integratorTypes();
// The keys every integrator object takes: "type".
const KeyList& integratorCommonKeys();
// Whether `type` declares the key named `name` (its canonical spelling).
bool declaresKey(const IntegratorType& type, const std::string& name);
// The table's lookup and list, as the commands spell them.
inline const IntegratorType* findIntegratorType(std::string_view spelling) {
  return integratorTypes().find(spelling);
}
inline std::string integratorTypeList() {
  return integratorTypes().names();
}
// The canonical names of the radiance estimators, in table order.
std::vector<std::string> radianceIntegrators();

}  // namespace verity
