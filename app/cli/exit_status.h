// The exit statuses the `verity` commands share.
//
// Bad input (2) is anything the user can fix in what they gave: a command line that cannot be
// parsed, a value out of range, a file that cannot be read or written, a malformed scene or
// image. Every command reports it as `verity: error: ` followed by the option, file or JSON path
// it is about, and exits with kBadInputStatus.
//
// Not bad input: an interrupted render (kInterruptedStatus; the partial image is written), and a
// failure of the program or the machine rather than of what was given (out of memory, an
// internal error, the report's plotting script failing): kFailureStatus. compare and chi2 use 1
// for a verdict (DIFFER, FAILED) and chi2 3 for INCONCLUSIVE, so every failure of theirs is
// reported as bad input.
#pragma once

namespace verity {

inline constexpr int kFailureStatus = 1;
inline constexpr int kBadInputStatus = 2;
inline constexpr int kInterruptedStatus = 130;  // 128 + SIGINT, as shells report it

}  // namespace verity
