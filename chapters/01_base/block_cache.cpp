// The block cache: a list of freed large blocks, oldest first, under one lock. Large blocks
// are few (a build frees a handful), so a linear search and a mutex cost nothing next to
// the megabytes each block stands for.
#include "01_base/block_cache.h"

#include <mutex>
#include <new>
#include <vector>

#include "01_base/aligned.h"

// A cached block is freed memory: under AddressSanitizer it is poisoned while it waits, so
// that a use after aligned_free() is still reported (the macros do nothing in other builds).
#include <sanitizer/asan_interface.h>

namespace rtk {
namespace {

struct Block {
  void* p;
  std::size_t bytes;
};

void free_block(const Block& b) {
  ASAN_UNPOISON_MEMORY_REGION(b.p, b.bytes);
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
    ASAN_UNPOISON_MEMORY_REGION(p, bytes);
    return p;
  }
  return nullptr;
}

void keep_cached_block(void* p, std::size_t bytes) {
  if (bytes > kBlockCacheBytes) return free_block({p, bytes});
  BlockCache& c = cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  std::size_t oldest = 0;  // push out the blocks freed longest ago until this one fits
  while (c.bytes + bytes > kBlockCacheBytes) {
    c.bytes -= c.blocks[oldest].bytes;
    free_block(c.blocks[oldest++]);
  }
  c.blocks.erase(c.blocks.begin(), c.blocks.begin() + std::ptrdiff_t(oldest));
  ASAN_POISON_MEMORY_REGION(p, bytes);
  c.blocks.push_back({p, bytes});
  c.bytes += bytes;
}
// [ch01-block-cache-keep]

void release_cached_blocks() {
  BlockCache& c = cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  for (const Block& b : c.blocks) free_block(b);
  c.blocks.clear();  // keeps the reserved room
  c.bytes = 0;
}

std::size_t cached_block_bytes() {
  BlockCache& c = cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  return c.bytes;
}

}  // namespace rtk
