/// \file
/// A BVH4 or BVH8 whose leaves use any layout of this chapter, and its kernels.
#pragma once

#include <memory>
#include <span>

#include "01_base/isa_dispatch.h"
#include "03_bvh4/bvh4.h"
#include "02_bvh2/trace_kernels.h"
#include "06_layouts/triangle_layout.h"

namespace rtk {

/// A BVHN with leaves in one layout. The indexed layouts point into a copy of the
/// mesh's vertices that the structure owns, so the mesh it was made from may go away; the
/// structure can be moved but not copied (the blocks hold the copy's address).
template <int N>
struct LayoutBVH {
  TriangleLayout layout = TriangleLayout::triangle4;
  BVHN<N> bvh;
  std::unique_ptr<const TriangleMesh> shared;  ///< the indexed layouts' mesh copy, else null

  /// Memory held: nodes, leaf blocks, and the shared vertices of the indexed layouts.
  size_t bytes() const { return bvh.bytes() + (shared ? shared->vertices.size() * sizeof(Vec3f) : 0); }
};

/// Makes the structure from a build tree over `mesh` with make_bvh (03_bvh4/bvh4.h), whose
/// exceptions it passes on.
template <int N>
LayoutBVH<N> make_layout_bvh(const BuildTree<N>& tree, const TriangleMesh& mesh, TriangleLayout layout);

extern template LayoutBVH<4> make_layout_bvh<4>(const BuildTree<4>&, const TriangleMesh&, TriangleLayout);
extern template LayoutBVH<8> make_layout_bvh<8>(const BuildTree<8>&, const TriangleMesh&, TriangleLayout);

/// The node widths the layout kernels are compiled for.
inline constexpr int kLayoutWidths[] = {4, 8};

// [ch06-layout-kernels]
/// The kernels of each ISA for a layout BVH of width N (4 or 8) with leaves in `layout`, tested
/// with Möller-Trumbore: `structure` is the LayoutBVH's `bvh`. Chapter 7 adds the other tests.
RTK_DECLARE_FOR_EACH_ISA(template <int N> TraceKernels layout_kernels(TriangleLayout layout))

/// Closest hits through a layout BVH with the kernels of `isa` (Möller-Trumbore). Throws
/// std::invalid_argument when the spans differ in length.
template <int N>
void intersect(Isa isa, const LayoutBVH<N>& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  RTK_PICK_ISA(isa, layout_kernels<N>)(bvh.layout).intersect(&bvh.bvh, rays, hits);
}
/// Occlusion through a layout BVH with the kernels of `isa` (Möller-Trumbore).
template <int N>
void occluded(Isa isa, const LayoutBVH<N>& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  RTK_PICK_ISA(isa, layout_kernels<N>)(bvh.layout).occluded(&bvh.bvh, rays, occluded);
}
// [ch06-layout-kernels]

}  // namespace rtk
