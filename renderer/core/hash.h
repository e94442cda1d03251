// Integer hashing for seeding, so that random streams depend on their coordinates only.
#pragma once

#include <cstdint>
#include <string_view>

namespace verity {

// The splitmix64 finaliser (Steele, Lea and Flood 2014, "Fast Splittable Pseudorandom
// Number Generators"): a bijective 64-bit mix.
inline uint64_t mix64(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  x ^= x >> 31;
  return x;
}

// One more value folded into a hash: hashValues(a, b, c) == hashCombine(hashValues(a, b), c).
inline uint64_t hashCombine(uint64_t h, uint64_t value) {
  return mix64(h ^ (value + 0x9e3779b97f4a7c15ull));
}

template <typename... Rest>
uint64_t hashValues(uint64_t first, Rest... rest) {
  uint64_t h = mix64(first + 0x9e3779b97f4a7c15ull);
  ((h = hashCombine(h, static_cast<uint64_t>(rest))), ...);
  return h;
}

// A stable hash of a string (64-bit FNV-1a, Fowler, Noll and Vo), for seeds keyed by names:
// tests and studies fix their seeds by name, never by hand.
uint64_t hashString(std::string_view s);

// A pseudo-random permutation of [0, n), keyed by `key`: a 4-round Feistel network on the
// smallest power-of-four domain covering n, with cycle walking back into [0, n).
uint32_t permuteIndex(uint32_t i, uint32_t n, uint64_t key);

}  // namespace verity
