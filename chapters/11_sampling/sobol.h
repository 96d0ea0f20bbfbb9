/// \file
/// A (0,2)-sequence in base 2 (the first two Sobol dimensions) with hash-based Owen
/// scrambling, after Burley, "Practical Hash-based Owen Scrambling" (JCGT 9(4), 2020).
/// Points are 32-bit fixed-point fractions: bit 31 is the first binary digit.
#pragma once

#include <array>
#include <cstdint>

namespace rtk {

/// Reverses the order of the 32 bits (the radical inverse in base 2, as a fraction): the bytes
/// by one byte-swap instruction, then the bits of each byte in three swap steps.
constexpr uint32_t reverse_bits(uint32_t x) {
  x = __builtin_bswap32(x);
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  return ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
}

/// reverse_bits of both 32-bit halves of a word at once, each staying in its half.
constexpr uint64_t reverse_bits_pairwise(uint64_t x) {
  x = __builtin_bswap64(x);  // reverses the bytes, and swaps the halves ...
  x = (x >> 32) | (x << 32);  // ... which this swaps back
  x = ((x >> 1) & 0x5555555555555555ull) | ((x & 0x5555555555555555ull) << 1);
  x = ((x >> 2) & 0x3333333333333333ull) | ((x & 0x3333333333333333ull) << 2);
  return ((x >> 4) & 0x0f0f0f0f0f0f0f0full) | ((x & 0x0f0f0f0f0f0f0f0full) << 4);
}

// [ch11-sobol]
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
// [ch11-sobol]

// [ch11-owen]
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
// [ch11-owen]

// [ch11-sobol-reference]
/// The three scramble seeds of one padded dimension: the index shuffle and the two
/// coordinates' Owen scrambles.
struct SobolSeeds {
  uint32_t shuffle = 0, x = 0, y = 0;
};

/// Both coordinates (32-bit fractions) of sample `index` of one padded dimension, written as
/// the definition says: shuffle the index by a nested uniform scramble, take that point of the
/// (0,2)-sequence, Owen-scramble each coordinate. Seven bit reversals and a loop over the
/// shuffled index's 32 bits: the specification that the sampler's fast form must equal.
constexpr std::array<uint32_t, 2> sobol_owen_reference(uint32_t index, SobolSeeds seeds) {
  const uint32_t shuffled = owen_scramble(index, seeds.shuffle);
  return {owen_scramble(sobol_dim0(shuffled), seeds.x),
          owen_scramble(sobol_dim1(shuffled), seeds.y)};
}
// [ch11-sobol-reference]

// [ch11-sobol-zeta]
/// The second Sobol dimension with its input index `s` as is and its output reversed:
/// reverse_bits(sobol_dim1(s)). Pascal's triangle modulo 2 has a one in row i, column j when
/// the bits of i are a subset of the bits of j (Lucas's theorem), so output bit i is the xor
/// of the index bits j that contain i: a "superset sum", done for all 32 bits at once in five
/// steps, one per bit of the bit number, instead of a loop over the index's bits.
constexpr uint32_t sobol_dim1_reversed(uint32_t s) {
  s ^= (s >> 1) & 0x55555555u;   // bit numbers with bit 0 clear take in their neighbour
  s ^= (s >> 2) & 0x33333333u;   // ... bit 1
  s ^= (s >> 4) & 0x0f0f0f0fu;   // ... bit 2
  s ^= (s >> 8) & 0x00ff00ffu;   // ... bit 3
  s ^= (s >> 16) & 0x0000ffffu;  // ... bit 4
  return s;
}
// [ch11-sobol-zeta]

// [ch11-sobol-fast]
/// sobol_owen_reference in the form the sampler runs, given the index already bit-reversed
/// (once per pixel sample). The definition's scrambles all work on reversed words, so it
/// reverses seven times; here three reversals remain. The nested uniform scramble of the
/// index is the LK hash of the reversed index, and reversing that gives the shuffled index s.
/// The first coordinate of s's Sobol point is reverse_bits(s), so its reversal, which the Owen
/// scramble hashes, is s itself; the second's reversal is sobol_dim1_reversed(s). After the
/// two hashes, one reversal of both coordinates at once (a 64-bit word) gives the fractions.
constexpr std::array<uint32_t, 2> sobol_owen(uint32_t reversed_index, SobolSeeds seeds) {
  const uint32_t s = reverse_bits(lk_hash(reversed_index, seeds.shuffle));
  const uint64_t both = (static_cast<uint64_t>(lk_hash(s, seeds.x)) << 32) |
                        lk_hash(sobol_dim1_reversed(s), seeds.y);
  const uint64_t r = reverse_bits_pairwise(both);
  return {static_cast<uint32_t>(r >> 32), static_cast<uint32_t>(r)};
}

/// The first coordinate alone (a 1D dimension): two hashes, two reversals.
constexpr uint32_t sobol_owen_1d(uint32_t reversed_index, SobolSeeds seeds) {
  return reverse_bits(lk_hash(reverse_bits(lk_hash(reversed_index, seeds.shuffle)), seeds.x));
}
// [ch11-sobol-fast]

}  // namespace rtk
