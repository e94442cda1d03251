// Test support: the message of the VerityError a callable throws, so that a test can assert
// on what an error names (the file, the JSON path or option, the problem).
#pragma once

#include <string>

#include "core/error.h"

namespace verity {

// The message of the VerityError that `f` throws, or "" when it throws none.
template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const VerityError& e) {
    return e.what();
  }
  return "";
}

}  // namespace verity
