// Radical inverses, plain and randomized, held exactly: the value is numerator / denominator
// with the denominator a power of the base, so that tests can check digits, not roundings.
#pragma once

#include <cstdint>

namespace verity {

// How the base-b digits a_j of the index are permuted before they are mirrored about the
// radix point (x = sum_j pi_j(a_j) b^-(j+1)).
enum class DigitScramble {
  None,           // pi_j = identity: the radical inverse itself
  PermuteDigits,  // one random permutation per digit position j (Matousek 1998)
  Owen,           // pi_j keyed by the digits a_0..a_{j-1} too: nested scrambling (Owen 1995,
                  // "Randomly permuted (t,m,s)-nets and (t,s)-sequences")
};

struct DigitFraction {
  uint64_t numerator = 0;
  uint64_t denominator = 1;  // a power of the base
};

// The radical inverse of `index` (below 2^32) in `base` (a prime, below 2^20) under `scramble`
// keyed by `key`. Scrambled inverses carry digits down to below 2^-24, the resolution of a float
// sample in [0, 1), so that even digits beyond the index's own are randomized.
//
// The permutation of each digit is affine, pi(a) = (m a + s) mod b, with m (non-zero) and s
// drawn from a hash. As b is prime, the images of any two distinct digits are a uniformly
// random pair of distinct digits. The mean and the variance of an estimate involve the points
// only one and two at a time, so such permutations give the same mean and variance as
// uniformly random ones (Matousek 1998, "On the L2-discrepancy for anchored boxes"; Owen 1997,
// "Monte Carlo variance of scrambled net quadrature"), at one hash per digit.
DigitFraction radicalInverse(uint32_t index, uint32_t base,
                             DigitScramble scramble = DigitScramble::None, uint64_t key = 0);

// numerator / denominator as a float in [0, 1).
float unitFloat(const DigitFraction& x);

}  // namespace verity
