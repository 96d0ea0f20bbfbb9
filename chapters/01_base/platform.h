/// \file
/// Compiler and bit-twiddling helpers that every chapter uses.
#pragma once

#include <bit>
#include <cstdint>

/// Forces inlining where the compiler's heuristics would otherwise keep a call in a hot loop.
#define RTK_INLINE inline __attribute__((always_inline))

/// Branch hints for the rare paths of traversal loops (empty stack, degenerate input).
#define RTK_LIKELY(x) __builtin_expect(!!(x), 1)
#define RTK_UNLIKELY(x) __builtin_expect(!!(x), 0)

namespace rtk {

/// Index of the lowest set bit (`bsf`/`tzcnt`); the mask must not be zero.
RTK_INLINE int bit_scan_forward(uint32_t mask) { return std::countr_zero(mask); }

/// Index of the lowest set bit, which is cleared from the mask (`bsf` then `btc`).
RTK_INLINE int pop_lowest_bit(uint32_t& mask) {
  const int index = std::countr_zero(mask);
  mask &= mask - 1;
  return index;
}

/// Index of the highest set bit, which is cleared from the mask; the mask must not be zero.
RTK_INLINE int pop_highest_bit(uint32_t& mask) {
  const int index = 31 - std::countl_zero(mask);
  mask &= ~(uint32_t(1) << index);
  return index;
}

/// Asks the cache for the line holding `address`, to be read soon (`prefetcht0`). A hint only:
/// it never faults and changes no result, so every ISA may use it.
RTK_INLINE void prefetch_l1(const void* address) { __builtin_prefetch(address, 0, 3); }

/// Number of set bits.
RTK_INLINE int pop_count(uint32_t mask) { return std::popcount(mask); }

/// `take_b ? b : a`, by masks rather than a branch. For a condition that depends on random data
/// (which side of a plane, which axis is nearer) a branch is mispredicted about half the time,
/// and compilers turn a plain `?:` of such a condition back into a branch when they judge it
/// cheaper.
RTK_INLINE uint32_t select_bits(bool take_b, uint32_t a, uint32_t b) {
  return a ^ ((a ^ b) & (0u - uint32_t(take_b)));
}
/// The same for floats, on their bits.
RTK_INLINE float select_bits(bool take_b, float a, float b) {
  return std::bit_cast<float>(select_bits(take_b, std::bit_cast<uint32_t>(a), std::bit_cast<uint32_t>(b)));
}

/// Iterates over the indices of the set bits of a mask, lowest first:
/// `for (int i : set_bits(movemask(hit))) ...`.
class set_bits {
 public:
  explicit set_bits(uint32_t mask) : mask_(mask) {}
  struct iterator {
    uint32_t mask;
    int operator*() const { return std::countr_zero(mask); }
    iterator& operator++() {
      mask &= mask - 1;
      return *this;
    }
    bool operator!=(const iterator& other) const { return mask != other.mask; }
  };
  iterator begin() const { return {mask_}; }
  iterator end() const { return {0}; }

 private:
  uint32_t mask_;
};

}  // namespace rtk
