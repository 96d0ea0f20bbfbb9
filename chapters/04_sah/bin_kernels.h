/// \file
/// The two passes over primitives that fill bins, compiled once per instruction set: binning a
/// set, and partitioning a set while binning its two halves. They are where a build spends most
/// of its time (each primitive passes through them once per level of the tree), and what each
/// primitive does there is grow three bins, one per axis, by its box and its centroid: sixteen
/// floats per bin (Bin). SSE4 grows them four floats at a time; AVX2 and AVX-512 eight at a
/// time, a box or a centroid's bounds with one minimum. Every variant fills the same bins and
/// leaves the primitives in the same order: minimum is exact.
#pragma once

#include <cstdint>

#include "01_base/isa_dispatch.h"
#include "04_sah/binning.h"

namespace rtk {

// [ch04-bin-kernels]
/// Bins `count` primitives into `bins` (which keeps what it held before).
RTK_DECLARE_FOR_EACH_ISA(void bin_prims(const PrimRef* refs, uint32_t count,
                                        const sah::BinMapping& map, sah::Bins& bins))

/// Partitions `count` primitives in place by `plane` and bins each into its side's bins (which
/// keep what they held before). Returns the number that went left.
RTK_DECLARE_FOR_EACH_ISA(uint32_t partition_and_bin(PrimRef* refs, uint32_t count,
                                                    const sah::SplitPlane& plane,
                                                    const sah::ChildBins& out))
// [ch04-bin-kernels]

}  // namespace rtk
