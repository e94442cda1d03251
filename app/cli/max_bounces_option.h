// `--max-bounces N`, as every command that renders a scene spells it: the scene's value unless
// given, a whole number up to kMaxBouncesLimit.
#pragma once

#include <CLI/CLI.hpp>

namespace verity {

CLI::Option* addMaxBouncesOption(CLI::App* cmd, int& maxBounces);

}  // namespace verity
