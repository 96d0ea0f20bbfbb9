/// \file
/// A bounded cache of large freed blocks: a program that builds again and again (a benchmark, a
/// renderer of moving scenes) asks for the same large arrays every time, and memory the C
/// library has handed back to the system comes back as fresh pages that the kernel must map
/// and zero on first touch (chapter 1, "Large blocks on huge pages"). aligned_malloc() and
/// aligned_free() go through it for blocks of kHugePageBytes or more.
#pragma once

#include <cstddef>

namespace rtk {

// [ch01-block-cache]
/// The most bytes the cache holds at once. A block freed beyond it pushes out the blocks freed
/// longest ago; a block larger than this is never kept. A cap, not a pool: nothing is held
/// that a program did not free, and a program that builds once holds at most this much.
inline constexpr std::size_t kBlockCacheBytes = std::size_t(128) << 20;

/// A cached block of exactly `bytes` (a multiple of kHugePageBytes, aligned to it), taken out
/// of the cache; nullptr where the cache holds none of that size.
void* take_cached_block(std::size_t bytes);

/// Gives the block (`bytes`, a multiple of kHugePageBytes, from the aligned operator new with
/// kHugePageBytes alignment) to the cache, which keeps it or frees it.
void keep_cached_block(void* p, std::size_t bytes);

/// Frees every cached block; a program that is done building can give the memory back.
void release_cached_blocks();

/// The bytes the cache holds now.
std::size_t cached_block_bytes();
// [ch01-block-cache]

}  // namespace rtk
