#include "04_sah/partition.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "04_sah/bin_kernels.h"

namespace rtk::sah {

void bin_prims(const PrimRef* refs, uint32_t count, const BinMapping& map, Bins& bins, Isa isa) {
  RTK_PICK_ISA(isa, bin_prims)(refs, count, map, bins);
}

void parallel_bin_prims(const PrimRef* refs, uint32_t count, const BinMapping& map, Bins& bins,
                        Isa isa) {
  const uint32_t blocks = (count + kPartitionBlockPrims - 1) / kPartitionBlockPrims;
  tbb::enumerable_thread_specific<Bins> local([&] {
    Bins b;
    b.reset(map.num_bins);
    return b;
  });
  tbb::parallel_for(
      tbb::blocked_range<uint32_t>(0, blocks), [&](const tbb::blocked_range<uint32_t>& r) {
        Bins& b = local.local();
        for (uint32_t block = r.begin(); block != r.end(); ++block) {
          const uint32_t first = block * kPartitionBlockPrims;
          bin_prims(refs + first, std::min(kPartitionBlockPrims, count - first), map, b, isa);
        }
      });
  for (const Bins& b : local) bins.merge(b);
}

uint32_t partition_and_bin(PrimRef* refs, uint32_t count, const SplitPlane& plane,
                           const ChildBins& out, Isa isa) {
  return RTK_PICK_ISA(isa, partition_and_bin)(refs, count, plane, out);
}

namespace {

/// A run of array positions.
struct Run {
  uint32_t begin = 0, length = 0;
};

/// Positions [first, first + n) of the concatenation of `runs`, whose start offsets are `starts`.
template <class F>
void for_each_position(const std::vector<Run>& runs, const std::vector<uint32_t>& starts,
                       uint32_t first, uint32_t n, F&& f) {
  size_t r = size_t(std::upper_bound(starts.begin(), starts.end(), first) - starts.begin()) - 1;
  uint32_t offset = first - starts[r];
  for (uint32_t k = 0; k < n; ++k) {
    while (offset == runs[r].length) ++r, offset = 0;
    f(k, runs[r].begin + offset);
    ++offset;
  }
}

}  // namespace

// [ch04-parallel-partition]
uint32_t parallel_partition_and_bin(PrimRef* refs, uint32_t count, const SplitPlane& plane,
                                    const ChildBins& out, Isa isa) {
  // Partition every block on its own, binning as the serial partition does.
  const uint32_t blocks = (count + kPartitionBlockPrims - 1) / kPartitionBlockPrims;
  std::vector<uint32_t> left_in_block(blocks);
  struct Pair {
    Bins left, right;
  };
  tbb::enumerable_thread_specific<Pair> local([&] {
    Pair p;
    p.left.reset(out.left_map->num_bins);
    p.right.reset(out.right_map->num_bins);
    return p;
  });
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, blocks),
                    [&](const tbb::blocked_range<uint32_t>& r) {
                      Pair& p = local.local();
                      const ChildBins mine{out.left_map, &p.left, out.right_map, &p.right};
                      for (uint32_t block = r.begin(); block != r.end(); ++block) {
                        const uint32_t first = block * kPartitionBlockPrims;
                        const uint32_t n = std::min(kPartitionBlockPrims, count - first);
                        left_in_block[block] = partition_and_bin(refs + first, n, plane, mine, isa);
                      }
                    });
  out.left->reset(out.left_map->num_bins);
  out.right->reset(out.right_map->num_bins);
  for (const Pair& p : local) {
    out.left->merge(p.left);
    out.right->merge(p.right);
  }

  // Find the primitives on the wrong side of the global border `mid`: right ones below it,
  // left ones above it. There are as many of one as of the other.
  uint32_t mid = 0;
  for (uint32_t l : left_in_block) mid += l;
  std::vector<Run> wrong_right, wrong_left;
  std::vector<uint32_t> right_starts, left_starts;
  uint32_t misplaced = 0, misplaced_left = 0;
  for (uint32_t block = 0; block < blocks; ++block) {
    const uint32_t first = block * kPartitionBlockPrims;
    const uint32_t last = std::min(first + kPartitionBlockPrims, count);
    const uint32_t border = first + left_in_block[block];
    if (border < mid && border < last) {
      right_starts.push_back(misplaced);
      wrong_right.push_back({border, std::min(last, mid) - border});
      misplaced += wrong_right.back().length;
    }
    const uint32_t from = std::max(first, mid);
    if (from < border) {
      left_starts.push_back(misplaced_left);
      wrong_left.push_back({from, border - from});
      misplaced_left += wrong_left.back().length;
    }
  }

  // Swap the k-th misplaced right primitive with the k-th misplaced left one.
  const uint32_t chunks = (misplaced + kPartitionBlockPrims - 1) / kPartitionBlockPrims;
  tbb::parallel_for(uint32_t(0), chunks, [&](uint32_t chunk) {
    const uint32_t first = chunk * kPartitionBlockPrims;
    const uint32_t n = std::min(kPartitionBlockPrims, misplaced - first);
    std::vector<uint32_t> targets(n);
    for_each_position(wrong_left, left_starts, first, n,
                      [&](uint32_t k, uint32_t pos) { targets[k] = pos; });
    for_each_position(wrong_right, right_starts, first, n,
                      [&](uint32_t k, uint32_t pos) { std::swap(refs[pos], refs[targets[k]]); });
  });
  return mid;
}
// [ch04-parallel-partition]

}  // namespace rtk::sah
