#include "sampling/radical_inverse.h"

#include <algorithm>

#include "core/hash.h"
#include "core/math.h"

namespace verity {

DigitFraction radicalInverse(uint32_t index, uint32_t base, DigitScramble scramble, uint64_t key) {
  DigitFraction x;
  uint32_t rest = index;  // 32-bit: divisions are several times faster than 64-bit ones
  uint64_t prefix = 0;    // index mod base^j: the digits below position j, which Owen's keys read
  uint64_t weight = 1;    // base^j
  // Plain inverses stop with the index's digits; scrambled ones go on to below 2^-24.
  for (int j = 0; rest > 0 || (scramble != DigitScramble::None && x.denominator < (1u << 24));
       ++j) {
    // Past the index's digits every digit is 0: no division (a scrambled base-2 inverse of a
    // sample index below 2^11 has 13 such digits of its 24).
    uint32_t digit = 0;
    if (rest > 0) {
      const uint32_t next = rest / base;
      digit = rest - next * base;
      rest = next;
    }
    uint32_t permuted = digit;
    if (scramble != DigitScramble::None) {
      const uint64_t h =
          scramble == DigitScramble::Owen ? hashValues(key, j, prefix) : hashValues(key, j);
      // m in [1, base) and s in [0, base) by multiply-and-shift (bias below base / 2^32).
      const uint32_t m = 1 + static_cast<uint32_t>(((h & 0xffffffffu) * (base - 1)) >> 32);
      const uint32_t s = static_cast<uint32_t>(((h >> 32) * base) >> 32);
      // m·digit + s < base², which 32 bits hold for bases below 2^16; 0 maps to s itself.
      if (digit == 0)
        permuted = s;
      else if (base < (1u << 16))
        permuted = (m * digit + s) % base;
      else
        permuted = static_cast<uint32_t>((uint64_t(m) * digit + s) % base);
    }
    x.numerator = x.numerator * base + permuted;
    x.denominator *= base;
    prefix += digit * weight;
    weight *= base;
  }
  return x;
}

float unitFloat(const DigitFraction& x) {
  const double value = static_cast<double>(x.numerator) / static_cast<double>(x.denominator);
  return std::min(static_cast<float>(value), kOneMinusEpsilon);
}

}  // namespace verity
