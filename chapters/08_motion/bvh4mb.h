/// \file
/// BVH4MB (and BVH8MB): the guide's motion-blur BVH (section 4.7). Each child carries two
/// boxes, at shutter times 0 and 1, and a ray at time t tests the box interpolated at t; the
/// leaves are triangle4i blocks whose vertices are interpolated before the triangle test.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "01_base/isa_dispatch.h"
#include "01_base/ray.h"
#include "02_bvh2/node_ref.h"
#include "02_bvh2/trace_kernels.h"
#include "04_sah/sah_options.h"
#include "07_intersectors/intersector_kind.h"
#include "08_motion/motion_mesh.h"

namespace rtk {

// [ch08-node]
/// A node of N moving children. The first six rows are the children's boxes at time 0, in the
/// order of chapter 3's NodeN (lower_x, upper_x, lower_y, ...: the near row of an axis is then
/// chosen once per ray by the sign of its direction); the next six rows are how far each plane
/// moves by time 1, in the same order, so that the plane a ray needs at time t is
/// `row + t * row[6]`, one multiplication and one addition. Storing the motion rather than the
/// box at time 1 saves a subtraction per plane and makes a static child exact at every time.
/// A Node4MB is 12 x 16 + 4 x 8 = 224 bytes, padded to four cache lines.
template <int N>
struct alignas(64) NodeMB {
  float lower_x[N], upper_x[N], lower_y[N], upper_y[N], lower_z[N], upper_z[N];
  float dlower_x[N], dupper_x[N], dlower_y[N], dupper_y[N], dlower_z[N], dupper_z[N];
  NodeRef children[N];  ///< kEmptyLeaf for an unused slot
};
static_assert(sizeof(NodeMB<4>) == 256, "a Node4MB is 224 bytes of data in four cache lines");
static_assert(sizeof(NodeMB<8>) == 448, "a Node8MB is 448 bytes, seven cache lines");
static_assert(offsetof(NodeMB<4>, dlower_x) == 6 * 4 * sizeof(float), "the motion rows follow the six box rows");
// [ch08-node]

/// The deepest tree the motion traversal's stack holds.
inline constexpr int kBvhMbMaxDepth = 64;

/// A motion-blur BVH with N-wide nodes. It owns its moving mesh: the triangle4i leaf blocks
/// point into `mesh.base.vertices`, so the structure may be moved but not copied.
template <int N>
struct BVHMB {
  static constexpr int kWidth = N;
  MotionMesh mesh;                    ///< the triangles, their vertices at time 0 and their motion
  IntersectorKind intersector = IntersectorKind::moeller;  ///< the triangle test of the leaves
  aligned_vector<NodeMB<N>> nodes;    ///< inner nodes; the root node, if any, is nodes[0]
  LeafBlocks leaves;                  ///< triangle4i blocks in leaf order
  NodeRef root = kEmptyLeaf;          ///< an inner node, or a leaf for tiny scenes
  Box3f bounds0, bounds1;             ///< the scene's boxes at times 0 and 1
  int depth = 0;                      ///< inner nodes on the longest root-to-leaf path

  /// An empty structure; build_bvhmb() makes real ones. Moving keeps the leaves' vertex
  /// addresses valid (a vector's buffer moves with it); copying would not, so it is deleted.
  BVHMB() = default;
  BVHMB(BVHMB&&) noexcept = default;
  BVHMB& operator=(BVHMB&&) noexcept = default;
  BVHMB(const BVHMB&) = delete;
  BVHMB& operator=(const BVHMB&) = delete;

  /// Bytes of nodes and leaf blocks (the tree).
  size_t tree_bytes() const { return nodes.size() * sizeof(NodeMB<N>) + leaves.bytes.size(); }
  /// Everything held: the tree and the vertex data (positions, motion, slots).
  size_t bytes() const { return tree_bytes() + mesh.vertex_bytes(); }
  /// The node an inner reference names.
  const NodeMB<N>& node(NodeRef ref) const {
    return *reinterpret_cast<const NodeMB<N>*>(reinterpret_cast<const char*>(nodes.data()) + ref);
  }
};

using BVH4MB = BVHMB<4>;
using BVH8MB = BVHMB<8>;

/// Builds a motion-blur BVH over a moving mesh (see chapter.md, "Building over time"): chapter
/// 4's binned SAH over each triangle's box swept over the shutter, then each child's boxes at
/// times 0 and 1 from its triangles' vertices at those times, grown by the rounding bound of
/// their interpolation. `options` default to what chapter 6 uses for triangle4i leaves. The
/// intersector must be one the triangle4i layout supports (all three do). Triangles with a
/// non-finite vertex or motion are left out and never hit. Throws std::invalid_argument for a
/// tree deeper than kBvhMbMaxDepth or a mesh with more vertices than triangle4i can index.
template <int N>
BVHMB<N> build_bvhmb(MotionMesh mesh, IntersectorKind intersector = IntersectorKind::moeller,
                     const SahBuildOptions* options = nullptr);

extern template BVHMB<4> build_bvhmb<4>(MotionMesh, IntersectorKind, const SahBuildOptions*);
extern template BVHMB<8> build_bvhmb<8>(MotionMesh, IntersectorKind, const SahBuildOptions*);

/// The SAH options the motion builder uses by default (chapter 6's for triangle4i).
SahBuildOptions motion_sah_options();

// [ch08-kernels]
/// The kernels of each ISA for a BVHMB of width N (4 or 8) whose mesh is stored as `storage` and
/// whose leaves are tested with `intersector`: closest hits (hits[i] for rays[i]) and occlusion
/// (1 blocked, 0 free) of rays at their own times; `structure` is the BVHMB<N>. Rays that are
/// not motion rays (is_valid_motion_ray) miss. The kernels throw std::invalid_argument for
/// spans of different lengths.
RTK_DECLARE_FOR_EACH_ISA(template <int N> TraceKernels motion_kernels(MotionStorage storage, IntersectorKind intersector))

/// Closest hits through a BVH4MB or BVH8MB with the kernels of `isa`.
template <int N>
void intersect(Isa isa, const BVHMB<N>& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  RTK_PICK_ISA(isa, motion_kernels<N>)(bvh.mesh.storage, bvh.intersector).intersect(&bvh, rays, hits);
}
/// Occlusion through a BVH4MB or BVH8MB with the kernels of `isa`.
template <int N>
void occluded(Isa isa, const BVHMB<N>& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  RTK_PICK_ISA(isa, motion_kernels<N>)(bvh.mesh.storage, bvh.intersector).occluded(&bvh, rays, occluded);
}
// [ch08-kernels]

}  // namespace rtk
