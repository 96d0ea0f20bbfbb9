/// \file
/// What a builder produces: a tree of boxes over primitive references, independent of the node
/// layout that traversal will use. Chapter 2's median builder and chapter 4's SAH builder both
/// produce a BuildTree; BVH2 (chapter 2) and BVH4/BVH8 (chapter 3) are made from one.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

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

/// One reference per triangle of the mesh, in primID order. Zero-area triangles are kept (a
/// triangle's primID never changes); they are simply never hit.
std::vector<PrimRef> make_prim_refs(const TriangleMesh& mesh);

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
  std::vector<Node> nodes;         ///< inner nodes; children point to higher indices only
  std::vector<uint32_t> prim_ids;  ///< primitive IDs in leaf order (repeats after spatial splits)

  bool empty() const { return root.leaf_count == 0 && nodes.empty(); }
};

/// The surface area heuristic cost of a tree (MacDonald and Booth, "Heuristics for ray tracing
/// using space subdivision", 1990): the expected cost of a random ray that hits the root box,
/// sum over inner nodes of area/root_area * traversal_cost plus over leaves of
/// area/root_area * count * intersection_cost.
template <int N>
double sah_cost(const BuildTree<N>& tree, double traversal_cost = 1.0, double intersection_cost = 1.0);

extern template double sah_cost<2>(const BuildTree<2>&, double, double);
extern template double sah_cost<4>(const BuildTree<4>&, double, double);
extern template double sah_cost<8>(const BuildTree<8>&, double, double);

}  // namespace rtk
