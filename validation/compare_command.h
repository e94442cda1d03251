// `verity compare A.exr B.exr`: do two renders (made with --variance) estimate the same
// image? Per-tile Welch t-tests decided by Holm's procedure (validation/image_comparison.h).
// Exit status 0 when they agree, 1 when they differ, 2 on bad input.
#pragma once

#include <CLI/CLI.hpp>

namespace verity {

void addCompareCommand(CLI::App& app);

}  // namespace verity
