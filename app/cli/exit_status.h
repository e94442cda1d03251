// The exit status that every command gives input it cannot use: a command line that cannot be
// parsed, a value out of range, a file that cannot be read or written, a malformed scene.
// Each command documents its other statuses (compare: 1 DIFFER; chi2: 1 FAILED, 3
// INCONCLUSIVE; 130: interrupted).
#pragma once

namespace verity {

inline constexpr int kBadInputStatus = 2;

}  // namespace verity
