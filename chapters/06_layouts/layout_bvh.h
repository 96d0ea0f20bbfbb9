/// \file
/// A BVH2, BVH4 or BVH8 whose leaves use any layout of this chapter, and its kernels.
#pragma once

#include <memory>
#include <span>
#include <type_traits>

#include "01_base/isa_dispatch.h"
#include "02_bvh2/bvh2.h"
#include "03_bvh4/bvh4.h"
#include "02_bvh2/trace_kernels.h"
#include "06_layouts/triangle_layout.h"

namespace rtk {

// [ch06-layout-tree]
/// The node tree of a layout BVH of width N: chapter 2's BVH2, whose node packs both children
/// into one cache line, for two children, chapter 3's BVHN for four and eight. Both are made
/// from a build tree by a template over the leaf layout (make_bvh2, make_bvh) and traced by a
/// template over the leaf intersector, so every layout reaches every width through the same
/// two templates; layout_traversal.h picks the traversal.
template <int N>
using LayoutTree = std::conditional_t<N == 2, BVH2, BVHN<N>>;

/// Makes the node tree of width N with leaves in layout L, its nodes made by `loop`.
template <int N, LeafLayout L, class Loop = SerialLoop>
LayoutTree<N> make_layout_tree(const BuildTree<N>& tree, const TriangleMesh& mesh,
                               const Loop& loop = {}) {
  if constexpr (N == 2)
    return make_bvh2<L>(tree, mesh, loop);
  else
    return make_bvh<N, L>(tree, mesh, loop);
}
// [ch06-layout-tree]

/// A BVH2, BVH4 or BVH8 with leaves in one layout. The indexed layouts point into a copy of the
/// mesh's vertices that the structure owns, so the mesh it was made from may go away; the
/// structure can be moved but not copied (the blocks hold the copy's address).
template <int N>
struct LayoutBVH {
  TriangleLayout layout = TriangleLayout::triangle4;
  LayoutTree<N> bvh;
  std::unique_ptr<const TriangleMesh> shared;  ///< the indexed layouts' mesh copy, else null

  /// Memory held: nodes, leaf blocks, and the shared vertices of the indexed layouts.
  size_t bytes() const { return bvh.bytes() + (shared ? shared->vertices.size() * sizeof(Vec3f) : 0); }
};

/// Makes the structure from a build tree over `mesh` with make_layout_tree, whose exceptions
/// (those of make_bvh2 and make_bvh) it passes on. The nodes and their leaves are made by a
/// parallel loop: in the caller's TBB task arena with `threads` = 0, in an arena of `threads`
/// threads otherwise; the structure is the same, byte for byte, on any number.
template <int N>
LayoutBVH<N> make_layout_bvh(const BuildTree<N>& tree, const TriangleMesh& mesh,
                             TriangleLayout layout, int threads = 0);

extern template LayoutBVH<2> make_layout_bvh<2>(const BuildTree<2>&, const TriangleMesh&,
                                                TriangleLayout, int);
extern template LayoutBVH<4> make_layout_bvh<4>(const BuildTree<4>&, const TriangleMesh&,
                                                TriangleLayout, int);
extern template LayoutBVH<8> make_layout_bvh<8>(const BuildTree<8>&, const TriangleMesh&,
                                                TriangleLayout, int);

/// The node widths the layout kernels are compiled for.
inline constexpr int kLayoutWidths[] = {2, 4, 8};

// [ch06-layout-kernels]
/// The kernels of each ISA for a layout BVH of width N (2, 4 or 8) with leaves in `layout`, tested
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
