/// \file
/// Aligned storage: SIMD loads want 16-, 32- or 64-byte alignment, and BVH nodes want to sit
/// in as few cache lines as possible.
#pragma once

#include <cstddef>
#include <new>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rtk {

// [ch01-huge-pages]
/// Blocks of this size or more are aligned to it and backed by huge pages where the system
/// allows (see allocation_alignment()).
inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

/// The alignment for a block of `bytes`: `alignment`, or 2 MB for a block of 2 MB or more. A
/// build writes its large arrays (references, nodes, leaves) into fresh memory, and the kernel
/// maps fresh memory page by page as it is first touched: 4 KB pages cost one fault for every
/// 128 references of 32 bytes, and in a virtual machine each fault costs microseconds. A block
/// aligned to 2 MB can be mapped with 2 MB pages (advise_huge_pages()), 512 times fewer faults.
inline std::size_t allocation_alignment(std::size_t bytes, std::size_t alignment) {
  return bytes >= kHugePageBytes && alignment < kHugePageBytes ? kHugePageBytes : alignment;
}

/// Asks the kernel to map [p, p + bytes) with transparent huge pages (Linux, madvise
/// MADV_HUGEPAGE; systems where transparent huge pages are "always" on need no asking, and
/// where they are off the advice is ignored). It is advice: a refusal changes nothing but speed.
inline void advise_huge_pages(void* p, std::size_t bytes) {
#ifdef MADV_HUGEPAGE
  if (bytes >= kHugePageBytes) ::madvise(p, bytes, MADV_HUGEPAGE);
#else
  (void)p, (void)bytes;
#endif
}
// [ch01-huge-pages]

/// Allocates `bytes` aligned to `alignment` (a power of two; 2 MB and huge pages for blocks of
/// 2 MB or more) through the aligned operator new, so that a program that counts its
/// allocations there sees these too; throws std::bad_alloc on failure.
inline void* aligned_malloc(std::size_t bytes, std::size_t alignment) {
  alignment = allocation_alignment(bytes, alignment);
  void* p = ::operator new(bytes == 0 ? 1 : bytes, std::align_val_t(alignment));
  advise_huge_pages(p, bytes);
  return p;
}
/// Frees what aligned_malloc(bytes, alignment) returned.
inline void aligned_free(void* p, std::size_t bytes, std::size_t alignment) {
  ::operator delete(p, std::align_val_t(allocation_alignment(bytes, alignment)));
}

/// A standard allocator with a fixed alignment, for std::vector of SIMD-loaded data.
template <class T, std::size_t Alignment = 64>
struct AlignedAllocator {
  using value_type = T;
  template <class U> struct rebind { using other = AlignedAllocator<U, Alignment>; };
  AlignedAllocator() = default;
  template <class U> AlignedAllocator(const AlignedAllocator<U, Alignment>&) {}
  T* allocate(std::size_t n) { return static_cast<T*>(aligned_malloc(n * sizeof(T), Alignment)); }
  void deallocate(T* p, std::size_t n) { aligned_free(p, n * sizeof(T), Alignment); }
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
