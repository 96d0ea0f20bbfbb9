/// \file
/// What a builder produces: a tree of boxes over primitive references, independent of the node
/// layout that traversal will use. Chapter 2's median builder and chapter 4's SAH builder both
/// produce a BuildTree; BVH2 (chapter 2) and BVH4/BVH8 (chapter 3) are made from one.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "01_base/aligned.h"
#include "01_base/box3.h"
#include "01_base/triangle_mesh.h"

namespace rtk {

/// A primitive as the builder sees it: a box and the primitive's ID, 32 bytes so that a box
/// loads as two 16-byte vectors. Spatial splits (chapter 5) make several references to one
/// primitive, each with a box clipped to a part of the space.
struct alignas(16) PrimRef {
  Vec3f lower;
  uint32_t prim = 0;
  Vec3f upper;
  uint32_t unused = 0;

  PrimRef() = default;
  PrimRef(const Box3f& box, uint32_t id) : lower(box.lower), prim(id), upper(box.upper) {}
  Box3f box() const { return {lower, upper}; }
  Vec3f center2() const { return lower + upper; }
};
static_assert(sizeof(PrimRef) == 32, "two 16-byte halves: lower+id, upper+unused");

/// Whether all three vertex indices of triangle i lie within the mesh's vertex array.
inline bool vertex_indices_valid(const TriangleMesh& mesh, size_t i) {
  const size_t vertex_count = mesh.vertices.size();
  const auto& tri = mesh.triangles[i];
  return tri[0] < vertex_count && tri[1] < vertex_count && tri[2] < vertex_count;
}

/// Throws std::invalid_argument, naming the triangle and the index, for the first triangle of
/// [first, last) with a vertex index past the vertex array; returns when there is none.
void check_vertex_indices(const TriangleMesh& mesh, size_t first = 0, size_t last = SIZE_MAX);

// [ch02-prim-ref]
/// The reference of triangle i, whose vertex indices must be valid: the triangle's box, or a
/// NaN box when a vertex is NaN or infinite (no builder places it). Inline, because a builder
/// makes one per triangle: called across files, the test of nine coordinates and the box cost
/// more in calls and reloads than in arithmetic.
inline PrimRef make_prim_ref(const TriangleMesh& mesh, uint32_t i) {
  const Vec3f a = mesh.vertex(i, 0), b = mesh.vertex(i, 1), c = mesh.vertex(i, 2);
  // Non-finite vertices only give a non-finite box, which the builders leave out of the tree
  // (such a triangle can never be hit). Box3f::extend follows the SIMD min/max rule, under
  // which a NaN coordinate can vanish from a box: mark such a box as NaN outright. A finite
  // coordinate minus itself is 0 and any other is NaN, so one sum tests all nine.
  if (is_finite((a - a) + (b - b) + (c - c))) return PrimRef(Box3f(a).extend(b).extend(c), i);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  return PrimRef(Box3f(Vec3f(nan), Vec3f(nan)), i);
}
// [ch02-prim-ref]

/// One reference per triangle of the mesh, in primID order. Zero-area triangles are kept (a
/// triangle's primID never changes); they are simply never hit. A triangle with a NaN or
/// infinite vertex gets a NaN box, which no builder places. Throws std::invalid_argument,
/// naming the triangle, when a vertex index is out of range.
std::vector<PrimRef> make_prim_refs(const TriangleMesh& mesh);

/// Whether a builder can place the reference: a finite box with lower <= upper. Builders leave
/// other references (a triangle with a NaN or infinite vertex) out of the tree, so such a
/// triangle is never hit and never disturbs the boxes of the others.
inline bool is_buildable(const PrimRef& ref) {
  const Vec3f lo = ref.lower, hi = ref.upper;
  return is_finite(lo) && is_finite(hi) && lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z;
}

/// A tree whose inner nodes have 2 to N children. A child is either an inner node or a leaf; a
/// leaf is a range [first, first + count) of `prim_ids`.
template <int N>
struct BuildTree {
  struct Child {
    Box3f box;
    uint32_t index = 0;       ///< inner node: index in `nodes`; leaf: first entry in `prim_ids`
    uint32_t leaf_count = 0;  ///< 0 for an inner node, the number of primitives for a leaf
    bool is_leaf() const { return leaf_count != 0; }
  };
  struct Node {
    std::array<Child, N> children;
    int num_children = 0;
  };

  Child root;                      ///< the whole scene: an inner node or (small scenes) a leaf
  aligned_vector<Node> nodes;      ///< inner nodes; children point to higher indices only
  aligned_vector<uint32_t> prim_ids;  ///< primitive IDs in leaf order (repeats after spatial splits)

  bool empty() const { return root.leaf_count == 0 && nodes.empty(); }
};

/// The number of inner nodes on the longest path from the root down to a leaf: 0 when the
/// root is a leaf. Traversal stacks are sized from it. Throws std::invalid_argument when a
/// child names a node that does not come after its parent (the tree would not be a tree).
template <int N>
int tree_depth(const BuildTree<N>& tree) {
  if (tree.root.is_leaf() || tree.nodes.empty()) return 0;
  // Children come after their parents, so one forward pass settles every node's depth.
  std::vector<int> depth(tree.nodes.size(), 0);
  if (tree.root.index >= tree.nodes.size()) throw std::invalid_argument("the root names no node");
  depth[tree.root.index] = 1;
  int deepest = 1;
  for (size_t i = 0; i < tree.nodes.size(); ++i) {
    const auto& node = tree.nodes[i];
    for (int c = 0; c < node.num_children; ++c) {
      const auto& child = node.children[size_t(c)];
      if (child.is_leaf()) continue;
      if (child.index <= i || child.index >= tree.nodes.size())
        throw std::invalid_argument("node " + std::to_string(i) + " names node " +
                                    std::to_string(child.index) + ", which does not follow it");
      depth[child.index] = depth[i] + 1;
      deepest = depth[child.index] > deepest ? depth[child.index] : deepest;
    }
  }
  return deepest;
}

/// The inner nodes in depth-first order: a node, then the subtrees of its children in slot
/// order. BVH layouts store their nodes (and leaves) in this order, whatever order the builder
/// made them in, so that a subtree occupies one stretch of memory. Throws
/// std::invalid_argument unless every node is reached from the root exactly once.
template <int N>
std::vector<uint32_t> depth_first_order(const BuildTree<N>& tree) {
  std::vector<uint32_t> order;
  if (tree.root.is_leaf() || tree.nodes.empty()) return order;
  order.reserve(tree.nodes.size());
  std::vector<uint8_t> seen(tree.nodes.size(), 0);
  std::vector<uint32_t> todo = {tree.root.index};
  while (!todo.empty()) {
    const uint32_t i = todo.back();
    todo.pop_back();
    if (i >= tree.nodes.size() || seen[i])
      throw std::invalid_argument("node " + std::to_string(i) + " is missing or reached twice");
    seen[i] = 1;
    order.push_back(i);
    const auto& node = tree.nodes[i];
    if (node.num_children < 0 || node.num_children > N)
      throw std::invalid_argument("node " + std::to_string(i) + " has " +
                                  std::to_string(node.num_children) + " children");
    for (int c = node.num_children - 1; c >= 0; --c)
      if (!node.children[size_t(c)].is_leaf()) todo.push_back(node.children[size_t(c)].index);
  }
  if (order.size() != tree.nodes.size())
    throw std::invalid_argument("the tree holds nodes its root does not reach");
  return order;
}

/// The number of tests a leaf of `n` primitives costs when they are tested `leaf_block` at a
/// time (chapter 6's blocks): ceil(n / leaf_block).
inline uint32_t leaf_tests(uint32_t n, int leaf_block) {
  return uint32_t((uint64_t(n) + uint64_t(leaf_block) - 1) / uint64_t(leaf_block));
}

/// The surface area heuristic cost of a tree (MacDonald and Booth, "Heuristics for ray tracing
/// using space subdivision", 1990): the expected cost of a random ray that hits the root box,
/// sum over inner nodes of area/root_area * traversal_cost plus over leaves of
/// area/root_area * count * intersection_cost. Leaves whose primitives are tested `leaf_block`
/// at a time (chapter 6's blocks) count ceil(count / leaf_block) tests instead of count.
template <int N>
double sah_cost(const BuildTree<N>& tree, double traversal_cost = 1.0,
                double intersection_cost = 1.0, int leaf_block = 1);

extern template double sah_cost<2>(const BuildTree<2>&, double, double, int);
extern template double sah_cost<4>(const BuildTree<4>&, double, double, int);
extern template double sah_cost<8>(const BuildTree<8>&, double, double, int);
extern template double sah_cost<16>(const BuildTree<16>&, double, double, int);

}  // namespace rtk
