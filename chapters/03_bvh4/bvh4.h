/// \file
/// BVH4 and BVH8: nodes of four (eight) children with their boxes in SoA rows, as the guide's
/// section 4.1 describes for SSE (and AVX), and the kernels that trace rays through them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "01_base/isa_dispatch.h"
#include "01_base/ray.h"
#include "02_bvh2/build_tree.h"
#include "02_bvh2/leaf_placement.h"
#include "02_bvh2/node_ref.h"
#include "02_bvh2/trace_kernels.h"
#include "02_bvh2/triangle1.h"
#include "03_bvh4/traversal_stats.h"
#include "03_bvh4/tricks.h"

namespace rtk {

// [ch03-node]
/// A node of N children (N = 4, 8 or 16). Each bound of each axis is a row of N floats, one per
/// child: one aligned load gives the lower x planes of all children, and a ray tests all
/// children at once with N-wide vector operations. The rows of an axis sit next to each other
/// (lower_x, upper_x, lower_y, ...), so that the near plane of an axis is at a byte offset that
/// a ray chooses once from the sign of its direction. With 64-bit child references a Node4 is
/// 6 x 16 + 4 x 8 = 128 bytes, two cache lines, and a Node8 256 bytes, four: the sizes the
/// hardware fetches, with no padding.
template <int N>
struct alignas(64) NodeN {
  float lower_x[N], upper_x[N];
  float lower_y[N], upper_y[N];
  float lower_z[N], upper_z[N];
  NodeRef children[N];  ///< kEmptyLeaf for an unused slot
};
static_assert(sizeof(NodeN<4>) == 128, "a Node4 is two cache lines");
static_assert(sizeof(NodeN<8>) == 256, "a Node8 is four cache lines");
static_assert(sizeof(NodeN<16>) == 512, "a Node16 is eight cache lines");
// [ch03-node]

using Node4 = NodeN<4>;
using Node8 = NodeN<8>;

/// The deepest tree a BVH4/BVH8 traversal stack holds: a descent pushes at most N - 1 entries
/// per level. Deeper trees are refused when the structure is made.
inline constexpr int kBvhMaxDepth = 64;
/// Stack entries a traversal of an N-wide tree may need, and N spare: the sorted push of the
/// AVX-512 kernels writes a register's worth of entries beyond the ones it pushes.
template <int N>
inline constexpr int kBvhStackSize = kBvhMaxDepth * (N - 1) + 1 + N;

/// A BVH with N-wide nodes over a triangle mesh.
template <int N>
struct BVHN {
  static constexpr int kWidth = N;
  aligned_vector<NodeN<N>> nodes;  ///< inner nodes; the root node, if any, is nodes[0]
  LeafBlocks leaves;               ///< the leaves' primitive blocks in leaf order
  NodeRef root = kEmptyLeaf;       ///< an inner node, or a leaf for tiny scenes
  Box3f bounds;                    ///< the scene's box (empty for an empty scene)
  int depth = 0;                   ///< inner nodes on the longest root-to-leaf path

  /// Memory held by nodes and leaves.
  size_t bytes() const { return nodes.size() * sizeof(NodeN<N>) + leaves.bytes.size(); }
  /// The node an inner reference names.
  const NodeN<N>& node(NodeRef ref) const {
    return *reinterpret_cast<const NodeN<N>*>(reinterpret_cast<const char*>(nodes.data()) + ref);
  }
};

using BVH4 = BVHN<4>;
using BVH8 = BVHN<8>;
/// Sixteen children per node: one AVX-512 register per row. It pays a little on AVX-512
/// (chapter 3 measures it); the other ISAs run it too, with two or four registers per row.
using BVH16 = BVHN<16>;

// [ch03-make-bvh]
/// Turns a build tree of up to N children per node into a BVHN whose leaves use layout L.
/// Unused child slots get the box whose bounds are all +inf, which no ray enters (the
/// traversal clamps the ray's interval to finite values, see bvhn_traverser.h), and the
/// empty leaf. Throws std::invalid_argument for a tree that does not fit: a node with fewer
/// than two or more than N children, a leaf range outside prim_ids, a primitive ID not in the
/// mesh, a leaf of more than kMaxLeafBlocks blocks, or a tree deeper than kBvhMaxDepth. The
/// nodes are made by `loop(n, f)`, as chapter 2's make_bvh2() makes them.
template <int N, LeafLayout L = Triangle1Layout, class Loop = SerialLoop>
BVHN<N> make_bvh(const BuildTree<N>& tree, const TriangleMesh& mesh, const Loop& loop = {}) {
  BVHN<N> bvh;
  bvh.leaves.layout = std::string(L::kName);
  if (tree.empty()) return bvh;
  bvh.bounds = tree.root.box;
  bvh.depth = tree_depth(tree);
  if (bvh.depth > kBvhMaxDepth)
    throw std::invalid_argument("a tree of depth " + std::to_string(bvh.depth) +
                                " is deeper than the traversal stack allows (" +
                                std::to_string(kBvhMaxDepth) + ")");
  // Nodes, and the leaves' triangles with them, go to memory in depth-first order: a ray
  // that descends into a subtree finds its next nodes near the ones it has just read.
  constexpr float inf = std::numeric_limits<float>::infinity();
  const std::vector<uint32_t> order = depth_first_order(tree);
  for (const uint32_t i : order)
    if (tree.nodes[i].num_children < 2 || tree.nodes[i].num_children > N)
      throw std::invalid_argument("node " + std::to_string(i) + " has " +
                                  std::to_string(tree.nodes[i].num_children) + " children");
  std::vector<uint32_t> position(tree.nodes.size());
  for (size_t k = 0; k < order.size(); ++k) position[order[k]] = uint32_t(k);
  const LeafPlacement<L, N> leaves(tree, mesh, order, bvh.leaves);
  bvh.nodes.resize(tree.nodes.size());
  loop(order.size(), [&](size_t k) {
    const auto& in = tree.nodes[order[k]];
    NodeN<N>& out = bvh.nodes[k];
    size_t at = leaves.first(k);
    for (int c = 0; c < N; ++c) {
      const bool used = c < in.num_children;
      const auto& child = in.children[size_t(used ? c : 0)];
      const Box3f box = used ? child.box : Box3f(Vec3f(inf), Vec3f(inf));
      out.lower_x[c] = box.lower.x, out.upper_x[c] = box.upper.x;
      out.lower_y[c] = box.lower.y, out.upper_y[c] = box.upper.y;
      out.lower_z[c] = box.lower.z, out.upper_z[c] = box.upper.z;
      if (!used)
        out.children[c] = kEmptyLeaf;
      else if (child.is_leaf())
        out.children[c] = leaves.pack(child, at);
      else
        out.children[c] = make_inner_ref(size_t(position[child.index]) * sizeof(NodeN<N>));
    }
  });
  size_t at = leaves.first(order.size());
  bvh.root = tree.root.is_leaf() ? leaves.pack(tree.root, at) : make_inner_ref(0);
  return bvh;
}
// [ch03-make-bvh]

// [ch03-kernels]
// The kernels, one set per ISA and node width (4, 8, 16), with triangle1 leaves. rays[i] gives
// hits[i] (closest hit) or occluded[i] (1 if anything blocks [tnear, tfar], else 0); invalid
// rays (rtk::is_valid) miss. bvhn_kernels<N>() runs all tricks without statistics (the fast
// path, `structure` a BVHN<N>); the `_tricks` entries run any configuration of kTrickConfigs,
// counting into `stats` when it is not null. All throw std::invalid_argument when the spans
// differ in length or the trick configuration is not one of kTrickConfigs.
RTK_DECLARE_FOR_EACH_ISA(template <int N> TraceKernels bvhn_kernels())
RTK_DECLARE_FOR_EACH_ISA(template <int N> void intersect_bvhn_tricks(const BVHN<N>& bvh, const Tricks& tricks,
                                                                     std::span<const Ray> rays,
                                                                     std::span<Hit> hits, TraversalStats* stats))
RTK_DECLARE_FOR_EACH_ISA(template <int N> void occluded_bvhn_tricks(const BVHN<N>& bvh, const Tricks& tricks,
                                                                    std::span<const Ray> rays,
                                                                    std::span<uint8_t> occluded, TraversalStats* stats))

/// Closest hits through a BVH4, BVH8 or BVH16 with the kernels of `isa`, all tricks on. Throws
/// std::invalid_argument unless the leaves are triangle1 (and like the kernels).
template <int N>
void intersect(Isa isa, const BVHN<N>& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  require_layout(bvh.leaves, Triangle1Layout::kName);
  RTK_PICK_ISA(isa, bvhn_kernels<N>)().intersect(&bvh, rays, hits);
}
/// Occlusion through a BVH4, BVH8 or BVH16 with the kernels of `isa`, all tricks on.
template <int N>
void occluded(Isa isa, const BVHN<N>& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  require_layout(bvh.leaves, Triangle1Layout::kName);
  RTK_PICK_ISA(isa, bvhn_kernels<N>)().occluded(&bvh, rays, occluded);
}
/// Closest hits with a chosen trick configuration (one of kTrickConfigs), counting into
/// `stats` when it is not null.
template <int N>
void intersect(Isa isa, const BVHN<N>& bvh, const Tricks& tricks, std::span<const Ray> rays,
               std::span<Hit> hits, TraversalStats* stats = nullptr) {
  require_layout(bvh.leaves, Triangle1Layout::kName);
  RTK_PICK_ISA(isa, intersect_bvhn_tricks<N>)(bvh, tricks, rays, hits, stats);
}
/// Occlusion with a chosen trick configuration, counting into `stats` when it is not null.
template <int N>
void occluded(Isa isa, const BVHN<N>& bvh, const Tricks& tricks, std::span<const Ray> rays,
              std::span<uint8_t> occluded, TraversalStats* stats = nullptr) {
  require_layout(bvh.leaves, Triangle1Layout::kName);
  RTK_PICK_ISA(isa, occluded_bvhn_tricks<N>)(bvh, tricks, rays, occluded, stats);
}
// [ch03-kernels]

}  // namespace rtk
