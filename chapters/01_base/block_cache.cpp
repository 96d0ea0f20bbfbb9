// The block cache: a list of freed large blocks, oldest first, under one lock. Large blocks
// are few (a build frees a handful), so a linear search and a mutex cost nothing next to
// the megabytes each block stands for.
#include "01_base/block_cache.h"

#include <mutex>
#include <new>
#include <vector>

#include "01_base/aligned.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/asan_interface.h>
#endif

namespace rtk {
namespace {

// A cached block is freed memory: under AddressSanitizer it is poisoned while it waits, so
// that a use after aligned_free() is still reported.
void mark_freed(void* p, std::size_t bytes) {
#if defined(__SANITIZE_ADDRESS__)
  ASAN_POISON_MEMORY_REGION(p, bytes);
#else
  (void)p, (void)bytes;
#endif
}
void mark_allocated(void* p, std::size_t bytes) {
#if defined(__SANITIZE_ADDRESS__)
  ASAN_UNPOISON_MEMORY_REGION(p, bytes);
#else
  (void)p, (void)bytes;
#endif
}

struct Block {
  void* p;
  std::size_t bytes;
};

void free_block(const Block& b) {
  mark_allocated(b.p, b.bytes);
  ::operator delete(b.p, std::align_val_t(kHugePageBytes));
}

struct BlockCache {
  // Room for as many blocks as the cap allows, so that keeping one never allocates.
  BlockCache() { blocks.reserve(kBlockCacheBytes / kHugePageBytes); }
  std::mutex mutex;
  std::vector<Block> blocks;  // oldest first
  std::size_t bytes = 0;
};

// Never destroyed: a static object freed after main() returns still finds the cache.
BlockCache& cache() {
  static BlockCache& c = *new BlockCache;
  return c;
}

}  // namespace

// [ch01-block-cache-keep]
void* take_cached_block(std::size_t bytes) {
  BlockCache& c = cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  for (std::size_t i = c.blocks.size(); i-- > 0;) {  // the most recently freed first
    if (c.blocks[i].bytes != bytes) continue;
    void* p = c.blocks[i].p;
    c.blocks.erase(c.blocks.begin() + std::ptrdiff_t(i));
    c.bytes -= bytes;
    mark_allocated(p, bytes);
    return p;
  }
  return nullptr;
}

void keep_cached_block(void* p, std::size_t bytes) {
  if (bytes > kBlockCacheBytes) return free_block({p, bytes});
  std::vector<Block> evicted;
  evicted.reserve(kBlockCacheBytes / kHugePageBytes);  // no allocation under the lock
  {
    BlockCache& c = cache();
    std::lock_guard<std::mutex> lock(c.mutex);
    std::size_t oldest = 0;
    while (c.bytes + bytes > kBlockCacheBytes) c.bytes -= c.blocks[oldest++].bytes;
    evicted.assign(c.blocks.begin(), c.blocks.begin() + std::ptrdiff_t(oldest));
    c.blocks.erase(c.blocks.begin(), c.blocks.begin() + std::ptrdiff_t(oldest));
    mark_freed(p, bytes);
    c.blocks.push_back({p, bytes});
    c.bytes += bytes;
  }
  for (const Block& b : evicted) free_block(b);  // outside the lock: unmapping takes time
}
// [ch01-block-cache-keep]

void release_cached_blocks() {
  std::vector<Block> all;
  {
    BlockCache& c = cache();
    std::lock_guard<std::mutex> lock(c.mutex);
    all.swap(c.blocks);
    c.bytes = 0;
  }
  for (const Block& b : all) free_block(b);
}

std::size_t cached_block_bytes() {
  BlockCache& c = cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  return c.bytes;
}

}  // namespace rtk
