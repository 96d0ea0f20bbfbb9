/// \file
/// A BVH4 or BVH8 whose leaves use any layout of this chapter, tested with any intersector of
/// chapter 7 the layout supports: the configurations of the guide's `-tri` option.
#pragma once

#include <memory>
#include <span>

#include "01_base/isa_dispatch.h"
#include "03_bvh4/bvh4.h"
#include "06_layouts/triangle_config.h"

namespace rtk {

/// A BVHN with leaves in the layout of `config`. The indexed layouts point into a copy of the
/// mesh's vertices that the structure owns, so the mesh it was made from may go away; the
/// structure can be moved but not copied (the blocks hold the copy's address).
template <int N>
struct LayoutBVH {
  TriangleConfig config;
  BVHN<N> bvh;
  std::unique_ptr<const TriangleMesh> shared;  ///< the indexed layouts' mesh copy, else null

  /// Memory held: nodes, leaf blocks, and the shared vertices of the indexed layouts.
  size_t bytes() const { return bvh.bytes() + (shared ? shared->vertices.size() * sizeof(Vec3f) : 0); }
};

/// Makes the structure from a build tree over `mesh` (see make_bvh in 03_bvh4/bvh4.h, whose
/// exceptions it passes on), with every box grown by 2^-16 of the scene's extent so that the
/// traversal's rounding never culls a box whose triangle the intersector would hit (chapter 7,
/// "A watertight test needs a conservative traversal"). Throws std::invalid_argument for an
/// unsupported configuration.
template <int N>
LayoutBVH<N> make_layout_bvh(const BuildTree<N>& tree, const TriangleMesh& mesh, TriangleConfig config);

extern template LayoutBVH<4> make_layout_bvh<4>(const BuildTree<4>&, const TriangleMesh&, TriangleConfig);
extern template LayoutBVH<8> make_layout_bvh<8>(const BuildTree<8>&, const TriangleMesh&, TriangleConfig);

// The kernels, one set per ISA: closest hits (hits[i] for rays[i]) and occlusion (1 blocked,
// 0 free). Invalid rays miss. Throw std::invalid_argument for spans of different lengths.
RTK_DECLARE_FOR_EACH_ISA(void intersect_layout_bvh4(const LayoutBVH<4>& bvh, std::span<const Ray> rays, std::span<Hit> hits))
RTK_DECLARE_FOR_EACH_ISA(void occluded_layout_bvh4(const LayoutBVH<4>& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded))
RTK_DECLARE_FOR_EACH_ISA(void intersect_layout_bvh8(const LayoutBVH<8>& bvh, std::span<const Ray> rays, std::span<Hit> hits))
RTK_DECLARE_FOR_EACH_ISA(void occluded_layout_bvh8(const LayoutBVH<8>& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded))

/// Closest hits through a layout BVH4 with the kernels of `isa`.
inline void intersect(Isa isa, const LayoutBVH<4>& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  RTK_PICK_ISA(isa, intersect_layout_bvh4)(bvh, rays, hits);
}
/// Closest hits through a layout BVH8 with the kernels of `isa`.
inline void intersect(Isa isa, const LayoutBVH<8>& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  RTK_PICK_ISA(isa, intersect_layout_bvh8)(bvh, rays, hits);
}
/// Occlusion through a layout BVH4 with the kernels of `isa`.
inline void occluded(Isa isa, const LayoutBVH<4>& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  RTK_PICK_ISA(isa, occluded_layout_bvh4)(bvh, rays, occluded);
}
/// Occlusion through a layout BVH8 with the kernels of `isa`.
inline void occluded(Isa isa, const LayoutBVH<8>& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  RTK_PICK_ISA(isa, occluded_layout_bvh8)(bvh, rays, occluded);
}

}  // namespace rtk
