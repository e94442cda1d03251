#include "core/hash.h"

namespace verity {

uint64_t hashString(std::string_view s) {
  // The same function as Verity::chi2's seedFromName, which may depend on no Verity code.
  uint64_t h = 0xcbf29ce484222325ull;  // offset basis
  for (unsigned char c : s) {
    h ^= c;
    h *= 0x100000001b3ull;  // prime
  }
  return h;
}

uint32_t permuteIndex(uint32_t i, uint32_t n, uint64_t key) {
  if (n <= 1) return 0;
  int halfBits = 1;
  while ((uint64_t(1) << (2 * halfBits)) < n) ++halfBits;
  const uint32_t mask = (1u << halfBits) - 1;
  uint32_t x = i;
  do {
    uint32_t left = x >> halfBits, right = x & mask;
    for (uint32_t round = 0; round < 4; ++round) {
      const uint32_t f = static_cast<uint32_t>(hashValues(key, round, right)) & mask;
      const uint32_t next = left ^ f;
      left = right;
      right = next;
    }
    x = (left << halfBits) | right;
  } while (x >= n);
  return x;
}

}  // namespace verity
