/// \file
/// Hashing and a small random number generator. Every random number of the renderer is a
/// function of (pixel, sample index, dimension, seed) through these hashes, so an image never
/// depends on how many threads rendered it or in which order the tiles were done.
#pragma once

#include <cstdint>

namespace rtk {

/// A 64-bit finaliser with full avalanche (each input bit flips each output bit with
/// probability close to 1/2): the `splitmix64` mixer of Steele, Lea and Flood, "Fast
/// splittable pseudorandom number generators" (OOPSLA 2014).
constexpr uint64_t mix64(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  x ^= x >> 31;
  return x;
}

/// Folds one more value into a running hash. Order matters: hash(a, b) != hash(b, a).
constexpr uint64_t hash_combine(uint64_t h, uint64_t v) {
  return mix64(h ^ (v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2)));
}

/// The hash of a pixel and a seed: the root of all of that pixel's random numbers.
constexpr uint64_t hash_pixel(int x, int y, uint32_t seed) {
  return hash_combine(hash_combine(mix64(seed), static_cast<uint32_t>(x)),
                      static_cast<uint32_t>(y));
}

/// The top 24 bits of a 32-bit integer as a float in [0, 1): exact, and never 1.0 (a
/// warping function fed 1.0 may leave its domain).
constexpr float to_unit_float(uint32_t bits) { return static_cast<float>(bits >> 8) * 0x1p-24f; }

/// The PCG32 generator (O'Neill, "PCG: A Family of Simple Fast Space-Efficient Statistically
/// Good Algorithms for Random Number Generation", 2014): 64 bits of state, 32-bit output by a
/// permuted xorshift-rotate of the state.
class Pcg32 {
 public:
  /// A generator on stream `stream` started from `state`; equal arguments give equal
  /// sequences.
  explicit constexpr Pcg32(uint64_t state = 0x853c49e6748fea9bull,
                           uint64_t stream = 0xda3e39cb94b95bdbull) {
    seed(state, stream);
  }

  /// Restarts the generator (the constructor's arguments).
  constexpr void seed(uint64_t state, uint64_t stream) {
    inc_ = (stream << 1u) | 1u;
    state_ = 0;
    next_u32();
    state_ += state;
    next_u32();
  }

  /// The next 32 random bits.
  constexpr uint32_t next_u32() {
    const uint64_t old = state_;
    state_ = old * 0x5851f42d4c957f2dull + inc_;
    const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
  }

  /// A uniform float in [0, 1).
  constexpr float next_float() { return to_unit_float(next_u32()); }

  /// Steps past the next 32 bits without computing them: one step of the state alone.
  constexpr void skip() { state_ = state_ * 0x5851f42d4c957f2dull + inc_; }

 private:
  uint64_t state_ = 0;
  uint64_t inc_ = 1;
};

}  // namespace rtk
