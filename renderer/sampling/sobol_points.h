// The first two dimensions of the Sobol sequence in base 2 and their hash-based Owen
// scrambling. Values are 32-bit fractions (x / 2^32).
//
// Dimension 0 is the van der Corput sequence (the bits of the index mirrored about the radix
// point); dimension 1 is its companion from the primitive polynomial x + 1, whose generator
// matrix is Pascal's triangle mod 2 (Sobol 1967). Together their first 2^m points, and every
// aligned block of 2^m consecutive points, form a (0, m, 2)-net: each of the 2^m elementary
// intervals [a 2^-k, (a+1) 2^-k) x [c 2^-(m-k), (c+1) 2^-(m-k)) holds exactly one point.
#pragma once

#include <cstdint>

namespace verity {

// The bits of x in reverse order: the bytes swapped, then the bits within each byte.
constexpr uint32_t reverseBits(uint32_t x) {
  x = __builtin_bswap32(x);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  return ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
}

namespace detail {

// Dimension 1 of Sobol point `index`, bit by bit. Direction numbers: v_0 = 1/2,
// v_k = v_(k-1) xor v_(k-1)/2.
constexpr uint32_t sobolDimension1Bitwise(uint32_t index) {
  uint32_t x = 0;
  for (uint32_t v = 0x80000000u; index != 0; index >>= 1, v ^= v >> 1)
    if (index & 1) x ^= v;
  return x;
}

// The generator matrix is linear over GF(2), so a point is the xor of the images of its
// index's four bytes: tables of those images, built at compile time, replace the loop over
// 32 bits that a scrambled (full 32-bit) index would otherwise take.
// `mirrored` holds the same images with their bits reversed (reversal is linear too).
struct SobolDimension1Tables {
  uint32_t byte[4][256] = {}, mirrored[4][256] = {};
  constexpr SobolDimension1Tables() {
    for (int b = 0; b < 4; ++b)
      for (uint32_t v = 0; v < 256; ++v) {
        byte[b][v] = sobolDimension1Bitwise(v << (8 * b));
        mirrored[b][v] = reverseBits(byte[b][v]);
      }
  }
};
inline constexpr SobolDimension1Tables kSobolDimension1;

}  // namespace detail

namespace detail {
inline uint32_t sobolDimension1(uint32_t index, const uint32_t (&t)[4][256]) {
  return t[0][index & 0xff] ^ t[1][(index >> 8) & 0xff] ^ t[2][(index >> 16) & 0xff] ^
         t[3][index >> 24];
}
}  // namespace detail

// Dimension `dimension` (0 or 1) of Sobol point `index`.
inline uint32_t sobolSample(uint32_t index, int dimension) {
  if (dimension == 0) return reverseBits(index);
  return detail::sobolDimension1(index, detail::kSobolDimension1.byte);
}

// reverseBits(sobolSample(index, 1)), without the reversal.
inline uint32_t sobolDimension1Mirrored(uint32_t index) {
  return detail::sobolDimension1(index, detail::kSobolDimension1.mirrored);
}

// An Owen scramble of the bits of x (a random permutation of each bit keyed by the bits above
// it) by Burley's hash (Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4)):
// mirrored, the Laine-Karras style hash below changes each bit by a function of the bits
// below it alone (adding the seed carries upward; multiplying by an even constant reads only
// lower bits), so mirrored back it is a nested scramble, which keeps every (0, m, 2)-net a net.
inline uint32_t laineKarrasPermutation(uint32_t x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}
inline uint32_t nestedUniformScramble(uint32_t x, uint32_t seed) {
  return reverseBits(laineKarrasPermutation(reverseBits(x), seed));
}

}  // namespace verity
