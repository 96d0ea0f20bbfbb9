/// \file
/// Where a structure's leaves go, found before any is packed. Nodes and the leaves below them
/// are laid out in the depth-first order of the nodes (make_bvh2 here, make_bvh in chapter 3);
/// once every leaf's place is known, the nodes can be made in any order, one at a time or on
/// many threads at once (chapter 6 does that), and the result is the same, byte for byte.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "02_bvh2/build_tree.h"
#include "02_bvh2/node_ref.h"

namespace rtk {

/// Runs f(i) for i = 0, 1, ..., n - 1 in turn: how the structures are made unless a caller
/// passes a parallel loop with the same call, loop(n, f).
struct SerialLoop {
  template <class F>
  void operator()(size_t n, F&& f) const {
    for (size_t i = 0; i < n; ++i) f(i);
  }
};

// [ch02-leaf-placement]
/// The leaves of a build tree in layout L, placed where a depth-first walk of the nodes
/// `order` would append them: node by node, children in slot order, then the root if it is a
/// leaf. The constructor checks every leaf (its range in prim_ids, its triangles in the mesh,
/// its block count) and allocates the blocks of all of them at once, so that none is copied
/// and no spare capacity is left behind (memory that bytes() would not count); pack() then
/// fills one leaf and touches nothing else, so that many threads may pack different leaves.
template <LeafLayout L, int N>
class LeafPlacement {
 public:
  using Child = typename BuildTree<N>::Child;

  LeafPlacement(const BuildTree<N>& tree, const TriangleMesh& mesh, std::span<const uint32_t> order,
                LeafBlocks& leaves)
      : tree_(tree), mesh_(mesh), leaves_(leaves), first_(order.size() + 1) {
    size_t bytes = 0;
    for (size_t k = 0; k < order.size(); ++k) {
      first_[k] = bytes;
      const auto& node = tree.nodes[order[k]];
      for (int c = 0; c < node.num_children && c < N; ++c)
        if (node.children[size_t(c)].is_leaf()) bytes += size_of(node.children[size_t(c)]);
    }
    first_[order.size()] = bytes;
    if (tree.root.is_leaf()) bytes += size_of(tree.root);
    leaves.bytes.resize(bytes);
  }

  /// Where the first leaf of the k-th node of `order` goes (k = order.size(): the root leaf).
  size_t first(size_t k) const { return first_[k]; }

  /// Packs `leaf` at byte `at` of the blocks, returns its reference and moves `at` past it.
  NodeRef pack(const Child& leaf, size_t& at) const {
    const NodeRef ref = pack_leaf<L>(leaves_, at, mesh_, prims(leaf));
    at += leaf_blocks(ref) * sizeof(typename L::Block);  // 0 for the empty leaf
    return ref;
  }

 private:
  std::span<const uint32_t> prims(const Child& leaf) const {
    return {tree_.prim_ids.data() + leaf.index, leaf.leaf_count};
  }
  /// The bytes of a leaf's blocks, after checking the leaf.
  size_t size_of(const Child& leaf) const {
    if (size_t(leaf.index) + leaf.leaf_count > tree_.prim_ids.size())
      throw std::invalid_argument("a leaf names entries past the end of prim_ids");
    for (uint32_t prim : prims(leaf))
      if (prim >= mesh_.size())
        throw std::invalid_argument("the tree names triangle " + std::to_string(prim) +
                                    " of a mesh with " + std::to_string(mesh_.size()));
    return blocks_for_leaf<L>(leaf.leaf_count) * sizeof(typename L::Block);
  }

  const BuildTree<N>& tree_;
  const TriangleMesh& mesh_;
  LeafBlocks& leaves_;
  std::vector<size_t> first_;
};
// [ch02-leaf-placement]

}  // namespace rtk
