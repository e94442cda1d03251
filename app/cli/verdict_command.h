// Runs a command whose exit status is a verdict (compare, referee, chi2). Those commands use 1
// for the verdict (DIFFER, FAILED), so any exception is reported as bad input
// (exit_status.h): `verity: error: ` and the message, and kBadInputStatus.
#pragma once

#include <fmt/core.h>

#include <cstdio>
#include <exception>

#include "cli/exit_status.h"

namespace verity {

template <class Run>
int runVerdictCommand(Run&& run) {
  try {
    return run();
  } catch (const std::exception& e) {
    fmt::print(stderr, "verity: error: {}\n", e.what());
    return kBadInputStatus;
  }
}

}  // namespace verity
