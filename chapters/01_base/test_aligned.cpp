// Chapter 1: aligned storage, and the huge-page alignment of large blocks.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <thread>
#include <vector>

#include "01_base/aligned.h"

#include <sys/mman.h>
#include <unistd.h>

using namespace rtk;

// [ch01-test-huge-pages]
TEST_CASE("ch01: large blocks are aligned for huge pages, small ones as asked") {
  CHECK(allocation_alignment(64, 64) == 64);
  CHECK(allocation_alignment(kHugePageBytes - 1, 32) == 32);
  CHECK(allocation_alignment(kHugePageBytes, 64) == kHugePageBytes);
  CHECK(allocation_alignment(3 * kHugePageBytes, 4 * kHugePageBytes) == 4 * kHugePageBytes);
  for (const std::size_t bytes : {std::size_t(100), std::size_t(5) << 20}) {
    void* p = aligned_malloc(bytes, 64);
    CHECK(reinterpret_cast<std::uintptr_t>(p) % allocation_alignment(bytes, 64) == 0);
    std::memset(p, 1, bytes);  // the whole block is usable
    aligned_free(p, bytes, 64);
  }
  // A vector of aligned_vector's allocator lands on a 2 MB border once it is that large.
  aligned_vector<float> big(kHugePageBytes / sizeof(float));
  CHECK(reinterpret_cast<std::uintptr_t>(big.data()) % kHugePageBytes == 0);
}
// [ch01-test-huge-pages]

// [ch01-test-map-pages]
TEST_CASE("ch01: pages mapped now are resident before anything touches them, contents kept") {
  // A mapping of its own, so that its pages are fresh, and of small pages only, so that one
  // touched page does not bring its 2 MB neighbourhood in with it.
  const std::size_t page = std::size_t(::sysconf(_SC_PAGESIZE)), pages = 64;
  void* mapping = ::mmap(nullptr, pages * page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  REQUIRE(mapping != MAP_FAILED);
  ::madvise(mapping, pages * page, MADV_NOHUGEPAGE);
  char* block = static_cast<char*>(mapping);
  auto resident = [&](std::size_t first, std::size_t count) {
    std::vector<unsigned char> in_core(count);
    REQUIRE(::mincore(block + first * page, count * page, in_core.data()) == 0);
    std::size_t n = 0;
    for (const unsigned char c : in_core) n += c & 1;
    return n;
  };
  block[0] = 'a';  // written before the request
  CHECK(resident(1, pages - 1) == 0);
  // From inside page 3 to inside page 40: pages 3 to 40 are mapped, the others not.
  if (map_pages_now(block + 3 * page + 10, 37 * page)) {
    CHECK(resident(3, 38) == 38);
    CHECK(resident(1, 2) == 0);
    CHECK(resident(41, pages - 41) == 0);
    CHECK(block[0] == 'a');
    CHECK(block[3 * page + 10] == 0);  // fresh memory reads as zero, mapped early or not
  } else {
    MESSAGE("this system cannot map pages on request; map_pages_now changes nothing here");
  }
  CHECK(map_pages_now(block, 0));  // nothing to map
  ::munmap(mapping, pages * page);
}
// [ch01-test-map-pages]

// [ch01-test-block-cache]
TEST_CASE("ch01: a freed large block is handed out again, and the cache stays within its cap") {
  release_cached_blocks();
  REQUIRE(cached_block_bytes() == 0);
  const std::size_t bytes = 3 * kHugePageBytes + 100;  // rounded up to four huge pages
  void* first = aligned_malloc(bytes, 64);
  std::memset(first, 7, bytes);
  aligned_free(first, bytes, 64);
  CHECK(cached_block_bytes() == 4 * kHugePageBytes);
  void* other_size = aligned_malloc(kHugePageBytes, 64);  // a size the cache does not hold
  CHECK(other_size != first);
  void* again = aligned_malloc(bytes - 50, 64);  // also four huge pages: the same block
  CHECK(again == first);
  CHECK(cached_block_bytes() == 0);
  aligned_free(again, bytes - 50, 64);
  aligned_free(other_size, kHugePageBytes, 64);
  CHECK(cached_block_bytes() == 5 * kHugePageBytes);

  // Small blocks, and blocks asked with a larger alignment, never go to the cache.
  void* small = aligned_malloc(4096, 64);
  aligned_free(small, 4096, 64);
  void* wide = aligned_malloc(kHugePageBytes, 4 * kHugePageBytes);
  aligned_free(wide, kHugePageBytes, 4 * kHugePageBytes);
  CHECK(cached_block_bytes() == 5 * kHugePageBytes);

  // Freeing more than the cap keeps the most recently freed blocks, within the cap.
  const std::size_t block = 8 * kHugePageBytes;
  std::vector<void*> blocks;
  for (std::size_t i = 0; i < kBlockCacheBytes / block + 3; ++i) blocks.push_back(aligned_malloc(block, 64));
  for (void* p : blocks) aligned_free(p, block, 64);
  CHECK(cached_block_bytes() == kBlockCacheBytes / block * block);
  CHECK(aligned_malloc(block, 64) == blocks.back());  // the newest is served first
  aligned_free(blocks.back(), block, 64);

  // A block larger than the cap is freed at once.
  void* huge = aligned_malloc(kBlockCacheBytes + 1, 64);
  const std::size_t before = cached_block_bytes();
  aligned_free(huge, kBlockCacheBytes + 1, 64);
  CHECK(cached_block_bytes() == before);

  release_cached_blocks();
  CHECK(cached_block_bytes() == 0);
}

TEST_CASE("ch01: the block cache serves many threads at once") {
  release_cached_blocks();
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([t] {
      const std::size_t bytes = std::size_t(t + 1) * kHugePageBytes;
      for (int round = 0; round < 50; ++round) {
        auto* p = static_cast<unsigned char*>(aligned_malloc(bytes, 64));
        p[0] = p[bytes - 1] = static_cast<unsigned char>(round);  // owned by this thread alone
        aligned_free(p, bytes, 64);
      }
    });
  }
  for (std::thread& t : threads) t.join();
  CHECK(cached_block_bytes() <= kBlockCacheBytes);
  CHECK(cached_block_bytes() == 10 * kHugePageBytes);  // one block of each thread's size
  release_cached_blocks();
}
// [ch01-test-block-cache]
