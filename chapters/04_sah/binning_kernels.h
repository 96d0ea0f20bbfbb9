/// \file
/// The binning passes, the loops that read every primitive at every level of the tree,
/// compiled once per instruction set (binning_kernels.cpp). partition.h's bin_prims() and
/// partition_and_bin() pick one of these; every variant gives the same bins and the same
/// order of primitives, bit for bit.
#pragma once

#include <cstdint>

#include "01_base/isa_dispatch.h"
#include "04_sah/partition.h"

namespace rtk {

// [ch04-binning-declare]
RTK_DECLARE_FOR_EACH_ISA(void bin_prims(const PrimRef* refs, uint32_t count,
                                        const sah::BinMapping& map, sah::Bins& bins))
RTK_DECLARE_FOR_EACH_ISA(uint32_t partition_and_bin(PrimRef* refs, uint32_t count,
                                                    const sah::SplitPlane& plane,
                                                    const sah::ChildBins& out))
// [ch04-binning-declare]

}  // namespace rtk
