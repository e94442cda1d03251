// The samplers the statistical suites render with: the all-pairs comparison of the shipped
// scenes, rigid-motion invariance and the pbrt-v3 and pbrt-v4 cross-checks give their cases
// these samplers in turn, along the scenes and along the integrators, so that each sampler
// meets every integrator and scenes of every kind at no extra render time. Each batch keeps its
// own seed: for halton and sobol that is an independent randomization of the scrambles, so
// the batch means stay independent and the suites' Welch tests hold.
#pragma once

#include <array>
#include <string>

#include "loader/scene_loader.h"

namespace verity::validation {

inline constexpr std::array<const char*, 3> kSuiteSamplers = {"independent", "halton", "sobol"};

// The sampler of the case at (scene index, integrator index) of a suite.
const char* suiteSampler(int scene, int integrator);

// Replaces `file`'s sampler with a new one of registry type `type`, at `spp` per pixel.
void useSampler(SceneFile& file, const std::string& type, int spp);

}  // namespace verity::validation
