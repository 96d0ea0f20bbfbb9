/// \file
/// Tree rotations (Kensler, "Tree Rotations for Improving Bounding Volume Hierarchies", IEEE
/// Symposium on Interactive Ray Tracing 2008), generalised from binary to N-ary nodes. A
/// rotation swaps a child of a node with a grandchild, or two grandchildren, when that shrinks
/// the boxes of the children in between.
#pragma once

#include <cstddef>
#include <vector>

#include "02_bvh2/build_tree.h"

namespace rtk::sah {

// [ch04-grandchild-swaps]
/// The widest node whose search also swaps two grandchildren. Such swaps grow as N^4 / 2 (every
/// pair of children, every pair of their children: 96 in a BVH4 node, 1,792 in a BVH8 node)
/// against N^3 swaps of a child with a grandchild. Measured on the real meshes, they make a
/// fifth of what a BVH4's rotations gain on Sponza, but a twentieth of a BVH8's (under 0.2 % of
/// SAH) for a fifth of its build time (chapter 4, "Tree rotations").
inline constexpr int kGrandchildSwapWidth = 4;
// [ch04-grandchild-swaps]

/// Applies rotations to the subtree whose root is `nodes[0]`, bottom-up, for up to `rounds`
/// rounds (fewer if a round finds nothing); returns how many it applied. Nodes wider than
/// kGrandchildSwapWidth search swaps of a child with a grandchild only.
///
/// Why a swap changes the SAH by the traversal cost times the change of one or two areas: the
/// SAH sums, over every box below the root, area(box) times what entering it costs, and that
/// term does not depend on how deep the box sits. Swapping child c of node X with grandchild g
/// (a child of X's child p) moves the boxes of c and g, with their terms, to other levels, and
/// changes one box only: p's, which now bounds c instead of g. Swapping two grandchildren
/// changes the boxes of their two parents. A swap is made only when it shrinks the area by
/// more than a millionth, so float rounding can never make the SAH grow, and only when it does
/// not make the node's subtree taller: unchecked, rotations can stretch a chain-like subtree
/// far past the depth a traversal stack holds.
///
/// Rotations move subtrees across the index order: afterwards a child may have a lower index
/// than its parent, and the caller renumbers the nodes (see preorder()).
///
/// Most swaps are ruled out before they are priced exactly, by bounds and estimates that
/// never rule out a swap the exact price would choose; `price_every_swap` prices all of them
/// exactly instead, the slow reference that the tests hold the fast search to.
template <int N>
size_t rotate_tree(std::vector<typename BuildTree<N>::Node>& nodes, int rounds,
                   bool price_every_swap = false);

/// The nodes of the subtree rooted at `nodes[0]` in depth-first preorder, renumbered so that
/// every child has a higher index than its parent.
template <int N>
std::vector<typename BuildTree<N>::Node> preorder(
    const std::vector<typename BuildTree<N>::Node>& nodes);

}  // namespace rtk::sah
