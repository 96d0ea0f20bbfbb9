/// \file
/// Executing a split in the same pass that bins the two halves. Each primitive is read once
/// per level of the tree: it is sent left or right by its bin in the parent's mapping and, in
/// passing, dropped into the bins of the child it goes to (guide section 4.3.1: "evaluating the
/// heuristic for the left and right side while doing a split").
#pragma once

#include <cstdint>
#include <cstring>

#include "04_sah/binning.h"

namespace rtk::sah {

/// Where to cut a set: primitives whose bin on `axis` under `map` is below `pos` go left.
struct SplitPlane {
  const BinMapping* map = nullptr;
  int axis = 0;
  int pos = 0;

  /// The same decision for a primitive already read into lanes, with the vector arithmetic of
  /// BinMapping::bins(), which gives the same bin as bin().
  RTK_INLINE bool goes_left(const PrimLanes& p) const { return map->bins(p.centroid)[axis] < pos; }
  RTK_INLINE bool goes_left(const PrimRef& ref) const {
    float lo[3], hi[3];
    std::memcpy(lo, &ref.lower, sizeof lo);
    std::memcpy(hi, &ref.upper, sizeof hi);
    return map->bin(lo[axis] * 0.5f + hi[axis] * 0.5f, axis) <
           pos;  // the centroid, as in centroid()
  }
};

/// Where the two halves of a split are binned: each side's mapping (made from its centroid
/// bounds, known from the parent's bins) and the bins it fills.
struct ChildBins {
  const BinMapping* left_map = nullptr;
  Bins* left = nullptr;
  const BinMapping* right_map = nullptr;
  Bins* right = nullptr;
};

/// Bins `count` primitives into `bins` (which keeps what it held before).
void bin_prims(const PrimRef* refs, uint32_t count, const BinMapping& map, Bins& bins);

/// bin_prims() as a parallel loop over blocks; the bins come out the same as the serial ones.
void parallel_bin_prims(const PrimRef* refs, uint32_t count, const BinMapping& map, Bins& bins);

/// Partitions `count` primitives in place by `plane` and bins each into its side's bins (which
/// keep what they held before). Returns the number that went left.
uint32_t partition_and_bin(PrimRef* refs, uint32_t count, const SplitPlane& plane,
                           const ChildBins& out);

/// partition_and_bin() as parallel loops: the range is cut into blocks of kPartitionBlockPrims,
/// each block partitioned on its own, and the primitives that are then on the wrong side of the
/// global border swapped pairwise, the k-th misplaced right one with the k-th misplaced left
/// one. Where every primitive ends up depends on the blocks only, never on the threads. The bins
/// are reset first.
uint32_t parallel_partition_and_bin(PrimRef* refs, uint32_t count, const SplitPlane& plane,
                                    const ChildBins& out);

}  // namespace rtk::sah
