// Chapter 1: aligned storage, and the huge-page alignment of large blocks.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>

#include "01_base/aligned.h"

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
