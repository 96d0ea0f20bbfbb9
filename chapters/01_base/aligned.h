/// \file
/// Aligned storage: SIMD loads want 16-, 32- or 64-byte alignment, and BVH nodes want to sit
/// in as few cache lines as possible.
#pragma once

#include <cstddef>
#include <cstdint>
#include <new>
#include <utility>
#include <vector>

#include "01_base/block_cache.h"

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
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

// [ch01-map-pages]
/// Asks the kernel to map every page holding a byte of [p, p + bytes) now, writable, rather
/// than one page at a time as each is first touched (Linux 5.14's MADV_POPULATE_WRITE; what was
/// written there stays as it was). Fresh memory costs its mapping and zeroing wherever it is
/// first touched: a program that maps the pieces of a large block on several threads shares
/// that cost out, where the thread that would first write the block alone would pay all of it.
/// Returns whether the pages are mapped now; false where the system has no such request or
/// refuses it, and then they are mapped on first touch as always.
inline bool map_pages_now(void* p, std::size_t bytes) {
  if (bytes == 0) return true;  // nothing to map, on any system
#if defined(MADV_POPULATE_WRITE)
  static const std::uintptr_t page = std::uintptr_t(::sysconf(_SC_PAGESIZE));
  const std::uintptr_t first = reinterpret_cast<std::uintptr_t>(p) / page * page;
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes + page - 1) / page * page;
  return ::madvise(reinterpret_cast<void*>(first), end - first, MADV_POPULATE_WRITE) == 0;
#else
  (void)p, (void)bytes;
  return false;
#endif
}
// [ch01-map-pages]

/// The bytes aligned_malloc() takes for a block of `bytes`: large blocks are rounded up to whole
/// huge pages, so that arrays of nearly the same size share a size in the block cache.
inline std::size_t allocation_bytes(std::size_t bytes) {
  if (bytes == 0) return 1;
  return bytes >= kHugePageBytes ? (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes
                                 : bytes;
}

/// Whether a block goes through the block cache: 2 MB or more, aligned to 2 MB, no more.
inline bool is_cached_block(std::size_t size, std::size_t alignment) {
  return size >= kHugePageBytes && alignment == kHugePageBytes;
}

// [ch01-aligned-malloc]
/// Allocates `bytes` aligned to `alignment` (a power of two; 2 MB and huge pages for blocks of
/// 2 MB or more), taking a large block from the block cache where it holds one of the size and
/// otherwise from the aligned operator new, so that a program that counts its allocations there
/// sees these too; throws std::bad_alloc on failure.
inline void* aligned_malloc(std::size_t bytes, std::size_t alignment) {
  alignment = allocation_alignment(bytes, alignment);
  const std::size_t size = allocation_bytes(bytes);
  if (is_cached_block(size, alignment))
    if (void* p = take_cached_block(size)) return p;  // mapped and advised already
  void* p = ::operator new(size, std::align_val_t(alignment));
  advise_huge_pages(p, size);
  return p;
}
/// Frees what aligned_malloc(bytes, alignment) returned: a large block to the block cache.
inline void aligned_free(void* p, std::size_t bytes, std::size_t alignment) {
  if (!p) return;
  alignment = allocation_alignment(bytes, alignment);
  const std::size_t size = allocation_bytes(bytes);
  if (is_cached_block(size, alignment)) return keep_cached_block(p, size);
  ::operator delete(p, std::align_val_t(alignment));
}
// [ch01-aligned-malloc]

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
