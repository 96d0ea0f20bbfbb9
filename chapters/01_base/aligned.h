/// \file
/// Aligned storage: SIMD loads want 16-, 32- or 64-byte alignment, and BVH nodes want to sit
/// in as few cache lines as possible.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>
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

/// AlignedAllocator for storage that is written after it is sized, by its owners, possibly on
/// many threads: resize() default-initialises the new elements, which for bytes and plain
/// structs means it writes nothing, where a vector would first zero them all on one thread.
template <class T, std::size_t Alignment = 64>
struct UninitializedAlignedAllocator : AlignedAllocator<T, Alignment> {
  template <class U> struct rebind { using other = UninitializedAlignedAllocator<U, Alignment>; };
  UninitializedAlignedAllocator() = default;
  template <class U>
  UninitializedAlignedAllocator(const UninitializedAlignedAllocator<U, Alignment>&) {}
  template <class U> void construct(U* p) { ::new (static_cast<void*>(p)) U; }
  template <class U, class... Args> void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// An aligned vector whose resize() leaves new elements unwritten (see above).
template <class T>
using aligned_buffer = std::vector<T, UninitializedAlignedAllocator<T, 64>>;

}  // namespace rtk
