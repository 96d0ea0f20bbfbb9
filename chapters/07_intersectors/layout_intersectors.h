/// \file
/// This chapter's tests in chapter 6's layouts: a layout BVH traced with the intersector a `-tri`
/// string names. The vertex and indexed layouts take any of the three tests; the precomputed
/// ones (triangle1/4/8) Möller-Trumbore only (layout_supports).
#pragma once

#include <span>

#include "01_base/isa_dispatch.h"
#include "06_layouts/layout_bvh.h"
#include "07_intersectors/triangle_config.h"

namespace rtk {

// [ch07-layout-kernels]
/// The kernels of each ISA for a layout BVH of width N (2, 4 or 8) whose leaves are in
/// `config.layout`, tested with `config.intersector`: the leaf policy with_leaf_intersector
/// names, in chapter 6's traversal of that width. `structure` is the LayoutBVH's `bvh`. Throws
/// std::invalid_argument for an unsupported pair.
RTK_DECLARE_FOR_EACH_ISA(template <int N> TraceKernels intersector_kernels(TriangleConfig config))

/// Closest hits through a layout BVH with the intersector `kind` and the kernels of `isa`.
template <int N>
void intersect(Isa isa, const LayoutBVH<N>& bvh, IntersectorKind kind, std::span<const Ray> rays,
               std::span<Hit> hits) {
  RTK_PICK_ISA(isa, intersector_kernels<N>)({bvh.layout, kind}).intersect(&bvh.bvh, rays, hits);
}
/// Occlusion through a layout BVH with the intersector `kind` and the kernels of `isa`.
template <int N>
void occluded(Isa isa, const LayoutBVH<N>& bvh, IntersectorKind kind, std::span<const Ray> rays,
              std::span<uint8_t> occluded) {
  RTK_PICK_ISA(isa, intersector_kernels<N>)({bvh.layout, kind}).occluded(&bvh.bvh, rays, occluded);
}
// [ch07-layout-kernels]

/// BVH4 kernels without chapter 2's exit widening (Tricks::conservative_exits off), for the
/// chart of what the widening buys: triangle4.moeller, triangle4v.pluecker and
/// triangle4v.watertight for `kind`. `structure` is the LayoutBVH<4>'s `bvh`.
RTK_DECLARE_FOR_EACH_ISA(TraceKernels unwidened_bvh4_kernels(IntersectorKind kind))

}  // namespace rtk
