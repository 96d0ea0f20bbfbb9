/// \file
/// BVH2: the binary bounding volume hierarchy with the guide's SSE-friendly node (section 4.2),
/// and the kernels that trace rays through it.
#pragma once

#include <cstdint>
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

namespace rtk {

// [ch02-node2]
/// A binary node. Per axis, one 16-byte row holds both children's bounds in the order
/// (lower left, lower right, upper left, upper right): one load brings an axis's four planes,
/// and a ray that runs "right to left" on that axis (negative direction) meets the upper planes
/// first, which one shuffle swapping the row's halves puts in front. 64 bytes, one cache line:
/// three rows of bounds and two child references.
struct alignas(64) Node2 {
  float x[4];
  float y[4];
  float z[4];
  NodeRef children[2];
};
static_assert(sizeof(Node2) == 64, "a binary node is one cache line");
// [ch02-node2]

/// The traversal stack of BVH2 holds one entry per level at most (the farther child), plus the
/// bottom entry; trees deeper than this are refused when the BVH2 is made.
inline constexpr int kBvh2StackSize = 128;

/// A binary BVH over a triangle mesh: nodes (inner nodes only) and leaf blocks.
struct BVH2 {
  aligned_vector<Node2> nodes;  ///< the root node, if any, is nodes[0]
  LeafBlocks leaves;            ///< the leaves' triangles, in leaf order
  NodeRef root = kEmptyLeaf;    ///< the root: an inner node, or a leaf for tiny scenes
  Box3f bounds;                 ///< the scene's box (empty for an empty scene)
  int depth = 0;                ///< inner nodes on the longest root-to-leaf path

  /// Memory held by nodes and leaves.
  size_t bytes() const { return nodes.size() * sizeof(Node2) + leaves.bytes.size(); }
  /// The node an inner reference names.
  const Node2& node(NodeRef ref) const {
    return *reinterpret_cast<const Node2*>(reinterpret_cast<const char*>(nodes.data()) + ref);
  }
};

// [ch02-make-bvh2]
/// Turns a binary build tree over `mesh` into a BVH2 whose leaves use layout L. Throws
/// std::invalid_argument for a tree that does not fit: a node without exactly two children, a
/// leaf range outside prim_ids, a primitive ID not in the mesh, a leaf of more than
/// kMaxLeafBlocks blocks, or a tree deeper than the traversal stack. The nodes are made by
/// `loop(n, f)`, f(k) for the k-th node: in turn by default, on many threads with a parallel
/// loop (chapter 6); the structure is the same.
template <LeafLayout L = Triangle1Layout, class Loop = SerialLoop>
BVH2 make_bvh2(const BuildTree<2>& tree, const TriangleMesh& mesh, const Loop& loop = {}) {
  BVH2 bvh;
  bvh.leaves.layout = std::string(L::kName);
  if (tree.empty()) return bvh;
  bvh.bounds = tree.root.box;
  bvh.depth = tree_depth(tree);
  if (bvh.depth + 1 > kBvh2StackSize)
    throw std::invalid_argument("a binary tree of depth " + std::to_string(bvh.depth) +
                                " is deeper than the BVH2 traversal stack allows");
  // Nodes, and the leaves' triangles with them, go to memory in depth-first order.
  const std::vector<uint32_t> order = depth_first_order(tree);
  for (const uint32_t i : order)
    if (tree.nodes[i].num_children != 2)
      throw std::invalid_argument("binary node " + std::to_string(i) + " has " +
                                  std::to_string(tree.nodes[i].num_children) + " children");
  std::vector<uint32_t> position(tree.nodes.size());
  for (size_t k = 0; k < order.size(); ++k) position[order[k]] = uint32_t(k);
  const LeafPlacement<L, 2> leaves(tree, mesh, order, bvh.leaves);
  bvh.nodes.resize(order.size());
  loop(order.size(), [&](size_t k) {
    const auto& in = tree.nodes[order[k]];
    const Box3f& l = in.children[0].box;
    const Box3f& r = in.children[1].box;
    Node2& out = bvh.nodes[k];
    for (int axis = 0; axis < 3; ++axis) {
      float* row = axis == 0 ? out.x : axis == 1 ? out.y : out.z;
      row[0] = l.lower[axis], row[1] = r.lower[axis], row[2] = l.upper[axis], row[3] = r.upper[axis];
    }
    size_t at = leaves.first(k);
    for (int c = 0; c < 2; ++c) {
      const auto& child = in.children[size_t(c)];
      out.children[c] = child.is_leaf()
                            ? leaves.pack(child, at)
                            : make_inner_ref(size_t(position[child.index]) * sizeof(Node2));
    }
  });
  size_t at = leaves.first(order.size());
  bvh.root = tree.root.is_leaf() ? leaves.pack(tree.root, at) : make_inner_ref(0);
  return bvh;
}
// [ch02-make-bvh2]

// [ch02-kernels]
/// The BVH2 kernels of each ISA (triangle1 leaves, Möller-Trumbore): `structure` is a BVH2.
/// An array of independent single rays per call amortises the dispatch. Throws
/// std::invalid_argument when the spans differ in length.
RTK_DECLARE_FOR_EACH_ISA(TraceKernels bvh2_kernels())

/// The closest hits of `rays` with the kernels of `isa`. Throws std::invalid_argument when the
/// spans differ in length or the leaves are not triangle1.
inline void intersect(Isa isa, const BVH2& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  require_layout(bvh.leaves, Triangle1Layout::kName);
  RTK_PICK_ISA(isa, bvh2_kernels)().intersect(&bvh, rays, hits);
}
/// The occlusion of `rays` with the kernels of `isa`: 1 if anything blocks [tnear, tfar], else 0.
inline void occluded(Isa isa, const BVH2& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  require_layout(bvh.leaves, Triangle1Layout::kName);
  RTK_PICK_ISA(isa, bvh2_kernels)().occluded(&bvh, rays, occluded);
}
// [ch02-kernels]

}  // namespace rtk
