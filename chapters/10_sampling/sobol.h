/// \file
/// A (0,2)-sequence in base 2 (the first two Sobol dimensions) with hash-based Owen
/// scrambling, after Burley, "Practical Hash-based Owen Scrambling" (JCGT 9(4), 2020).
/// Points are 32-bit fixed-point fractions: bit 31 is the first binary digit.
#pragma once

#include <cstdint>

namespace rtk {

/// Reverses the order of the 32 bits (the radical inverse in base 2, as a fraction).
constexpr uint32_t reverse_bits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

// [ch10-sobol]
/// The first Sobol dimension: the van der Corput sequence, bit-reversed index.
constexpr uint32_t sobol_dim0(uint32_t index) { return reverse_bits(index); }

/// The second Sobol dimension. Its generator matrix is Pascal's triangle modulo 2, so each
/// direction number is the previous one xor-ed with itself shifted by one bit.
constexpr uint32_t sobol_dim1(uint32_t index) {
  uint32_t result = 0;
  for (uint32_t v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1)
    if (index & 1u) result ^= v;
  return result;
}
// [ch10-sobol]

// [ch10-owen]
/// A hash in which every bit depends only on itself and the bits below it (the property of
/// Laine and Karras's permutation), with the constants of Vegdahl, "Building a Better LK
/// Hash" (2021). Every step is a bijection: xor with an even multiple, add, odd multiply.
constexpr uint32_t lk_hash(uint32_t x, uint32_t seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

/// Owen scrambling of a fraction: digit d is flipped by a random function of the digits
/// before it. Reversing the bits turns the LK hash's "depends on lower bits" into "depends on
/// the more significant digits". Owen scrambling keeps every elementary interval's count, so a
/// scrambled (0,m,2)-net is still one.
constexpr uint32_t owen_scramble(uint32_t fraction, uint32_t seed) {
  return reverse_bits(lk_hash(reverse_bits(fraction), seed));
}
// [ch10-owen]

}  // namespace rtk
