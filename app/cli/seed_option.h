// The --seed option of the commands that render: a whole number from 0 to 2⁶⁴ − 1. Anything
// else (negative, fractional, larger) is refused by name; a parser that saturated or wrapped
// would render one image for many different seeds.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace verity {

// Adds "--seed" to `cmd`, stored in `seed`.
CLI::Option* addSeedOption(CLI::App* cmd, uint64_t& seed, const std::string& help);

}  // namespace verity
