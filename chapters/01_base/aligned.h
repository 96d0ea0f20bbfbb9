/// \file
/// Aligned storage: SIMD loads want 16-, 32- or 64-byte alignment, and BVH nodes want to sit
/// in as few cache lines as possible.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

namespace rtk {

/// Allocates `bytes` aligned to `alignment` (a power of two); throws std::bad_alloc on failure.
inline void* aligned_malloc(std::size_t bytes, std::size_t alignment) {
  const std::size_t rounded = (bytes + alignment - 1) / alignment * alignment;
  void* p = std::aligned_alloc(alignment, rounded == 0 ? alignment : rounded);
  if (!p) throw std::bad_alloc();
  return p;
}
inline void aligned_free(void* p) { std::free(p); }

/// A standard allocator with a fixed alignment, for std::vector of SIMD-loaded data.
template <class T, std::size_t Alignment = 64>
struct AlignedAllocator {
  using value_type = T;
  template <class U> struct rebind { using other = AlignedAllocator<U, Alignment>; };
  AlignedAllocator() = default;
  template <class U> AlignedAllocator(const AlignedAllocator<U, Alignment>&) {}
  T* allocate(std::size_t n) { return static_cast<T*>(aligned_malloc(n * sizeof(T), Alignment)); }
  void deallocate(T* p, std::size_t) { aligned_free(p); }
  template <class U> bool operator==(const AlignedAllocator<U, Alignment>&) const { return true; }
};

/// A vector whose data starts on a cache line.
template <class T>
using aligned_vector = std::vector<T, AlignedAllocator<T, 64>>;

}  // namespace rtk
