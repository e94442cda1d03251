// The integrator a render uses and its parameters, from the scene file and the command line.
// max_bounces counts scattering events: a path with k edges from the camera to an emitter
// has k − 1 bounces, so 0 shows emitters seen directly and 1 adds direct lighting. Every
// integrator, BDPT included, uses this meaning.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "integrators/bdpt.h"
#include "integrators/russian_roulette.h"
#include "params/json_node.h"

namespace verity {

// The largest max_bounces a scene or a command line may ask for (paths end by roulette long
// before; the limit keeps vertex counts such as max_bounces + 2 far from overflow).
inline constexpr int kMaxBouncesLimit = 1 << 20;
inline constexpr int kDefaultMaxBounces = 64;
inline constexpr float kDefaultMisPower = 1;  // the balance heuristic

struct IntegratorType;
// The integrator a scene gets when it names none.
const IntegratorType& defaultIntegratorType();

struct IntegratorSettings {
  const IntegratorType* type = &defaultIntegratorType();  // an entry of integratorTypes()
  int maxBounces = kDefaultMaxBounces;
  float misPower = kDefaultMisPower;  // 1: balance heuristic, 2: power heuristic
  // "rr_depth": the scattering event after which Russian roulette first decides whether a path
  // goes on (1: after the first); one larger than max_bounces turns the roulette off.
  int rrDepth = kDefaultRouletteDepth;
  // "rr_threshold": the throughput below which the roulette may end a path; unset, the type's
  // own (IntegratorType::rouletteThreshold), whichever type the command line picks.
  std::optional<float> rrThreshold;
  float aoDistance = kInfinity;  // occlusion radius for "ao"
  // Test hook, never read from a scene: a BDPT strategy whose contribution is left out.
  BdptStrategy bdptDroppedStrategy;
};

// The type spelled `name` (any accepted spelling); an unknown name is an error naming `option`
// and the known types.
const IntegratorType& integratorTypeNamed(const std::string& name, const std::string& option);
// What a command line changes in the scene's settings; each field at its default keeps the
// scene's value.
struct IntegratorOverrides {
  const IntegratorType* type = nullptr;
  int maxBounces = -1;
  int rrDepth = 0;        // an error (naming --rr-depth) for a type without Russian roulette
  float rrThreshold = 0;  // likewise (naming --rr-threshold)
};
// The overrides of `--integrator type` (empty: the scene's) and `--max-bounces` (negative:
// the scene's).
IntegratorOverrides integratorOverrides(const std::string& type, int maxBounces);
IntegratorSettings overrideIntegrator(IntegratorSettings settings,
                                      const IntegratorOverrides& overrides);
// Reads the scene's "integrator" object (null: the defaults).
IntegratorSettings parseIntegratorSettings(const JsonNode* node);
std::unique_ptr<Integrator> makeIntegrator(const IntegratorSettings& settings);
// The Russian roulette the settings ask for.
RussianRoulette makeRoulette(const IntegratorSettings& s);

}  // namespace verity
