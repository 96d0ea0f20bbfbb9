/// \file
/// Each ray against every triangle with one of the intersectors, K triangles at a time: the
/// kernels of chapter 7 without any acceleration structure, for the stability tests and the
/// leak measurements.
#pragma once

#include <span>

#include "01_base/isa_dispatch.h"
#include "01_base/ray.h"
#include "07_intersectors/intersector_kind.h"
#include "07_intersectors/triangle_soa.h"

namespace rtk {

/// The widths K (triangles per test) every ISA compiles the intersectors for.
inline constexpr int kIntersectorWidths[] = {1, 4, 8, 16};

// Closest hit of rays[i] into hits[i], testing `width` triangles at a time with the intersector
// `kind`. Invalid rays (rtk::is_valid) miss. Among hits at the same distance the lowest primID
// wins, so every width and ISA gives the same answer wherever the arithmetic is the same.
// Throws std::invalid_argument for a width that is not in kIntersectorWidths or for spans of
// different lengths.
RTK_DECLARE_FOR_EACH_ISA(void intersect_all(const TriangleSoA& triangles, IntersectorKind kind,
                                            int width, std::span<const Ray> rays,
                                            std::span<Hit> hits))

}  // namespace rtk
