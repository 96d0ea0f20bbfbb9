/// \file
/// The per-ISA entry points of the slab test (slab.h): for the tests, which compare every
/// variant and width with the scalar one, and for the benchmark.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "01_base/boxes_soa.h"
#include "01_base/isa_dispatch.h"
#include "01_base/ray.h"

namespace rtk {

/// The widths the slab kernels are compiled for (1 is a plain scalar loop over the boxes).
inline constexpr int kSlabWidths[] = {1, 4, 8, 16};

// [ch01-slab-declare]
// Tests one ray against every box of `boxes`, `width` boxes at a time, and writes, for each of
// the boxes.padded_count() boxes, hit[i] = 1 or 0 and entry[i], the distance at which the ray
// enters the box's interval. Throws std::invalid_argument for a width not in kSlabWidths or
// for boxes whose arrays are not padded consistently.
RTK_DECLARE_FOR_EACH_ISA(void intersect_boxes(int width, const Ray& ray, const BoxesSoA& boxes,
                                              uint8_t* hit, float* entry))

// The number of (ray, box) pairs that hit, over all rays and boxes: the benchmark's work.
RTK_DECLARE_FOR_EACH_ISA(uint64_t count_box_hits(int width, std::span<const Ray> rays,
                                                 const BoxesSoA& boxes))
// [ch01-slab-declare]

}  // namespace rtk
