/// \file
/// Executing a split in the same pass that bins the two halves. Each primitive is read once
/// per level of the tree: it is sent left or right by its bin in the parent's mapping and, in
/// passing, dropped into the bins of the child it goes to (guide section 4.3.1: "evaluating the
/// heuristic for the left and right side while doing a split"). The serial passes are
/// bin_kernels.h's, in the variant `isa`; this file runs them on one set, or on blocks of a
/// large set in parallel.
#pragma once

#include <cstdint>

#include "01_base/cpu_features.h"
#include "04_sah/binning.h"

namespace rtk::sah {

/// Bins `count` primitives into `bins` (which keeps what it held before).
void bin_prims(const PrimRef* refs, uint32_t count, const BinMapping& map, Bins& bins, Isa isa);

/// bin_prims() as a parallel loop over blocks; the bins come out the same as the serial ones.
void parallel_bin_prims(const PrimRef* refs, uint32_t count, const BinMapping& map, Bins& bins,
                        Isa isa);

/// Partitions `count` primitives in place by `plane` and bins each into its side's bins (which
/// keep what they held before). Returns the number that went left.
uint32_t partition_and_bin(PrimRef* refs, uint32_t count, const SplitPlane& plane,
                           const ChildBins& out, Isa isa);

/// partition_and_bin() as parallel loops: the range is cut into blocks of kPartitionBlockPrims,
/// each block partitioned on its own, and the primitives that are then on the wrong side of the
/// global border swapped pairwise, the k-th misplaced right one with the k-th misplaced left
/// one. Where every primitive ends up depends on the blocks only, never on the threads. The bins
/// are reset first.
uint32_t parallel_partition_and_bin(PrimRef* refs, uint32_t count, const SplitPlane& plane,
                                    const ChildBins& out, Isa isa);

}  // namespace rtk::sah
