/// \file
/// How a BVH node names its children, and where the leaves keep their triangles. Shared by
/// every node width (BVH2 here, BVH4 and BVH8 in chapter 3) and every leaf layout.
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "01_base/aligned.h"
#include "01_base/triangle_mesh.h"

namespace rtk {

// [ch02-node-ref]
/// A child reference, 64 bits. An inner node is named by its byte offset in the node array (a
/// multiple of 64: nodes are cache-line aligned), so bit 0 is clear and finding the node is one
/// addition. A leaf has bit 0 set, the number of its primitive blocks (0 to 15) in bits 1-4 and
/// the byte offset of its first block in the leaf array (a multiple of 16) from bit 5 on:
/// `ref >> 1` is then that offset plus the count.
using NodeRef = uint64_t;

/// The most primitive blocks one leaf reference can count.
inline constexpr uint32_t kMaxLeafBlocks = 15;
/// The reference of a leaf with no primitives (the tree of an empty scene; unused child slots).
inline constexpr NodeRef kEmptyLeaf = 1;
/// A reference no tree contains: the bottom of every traversal stack.
inline constexpr NodeRef kTerminal = ~NodeRef(0);

constexpr bool is_leaf(NodeRef ref) { return (ref & 1) != 0; }
constexpr NodeRef make_inner_ref(size_t node_byte_offset) { return NodeRef(node_byte_offset); }
constexpr NodeRef make_leaf_ref(size_t block_byte_offset, uint32_t blocks) {
  return (NodeRef(block_byte_offset) << 1) | (NodeRef(blocks) << 1) | 1;
}
constexpr size_t leaf_offset(NodeRef ref) { return size_t(ref >> 1) & ~size_t(15); }
constexpr uint32_t leaf_blocks(NodeRef ref) { return uint32_t(ref >> 1) & 15; }
// [ch02-node-ref]

/// The primitive blocks of every leaf of a BVH, one after the other in leaf order, in the layout
/// named `layout`. Traversal is generic over the layout; the kernels check the name before they
/// read the bytes as blocks of their type.
struct LeafBlocks {
  std::string layout;               ///< e.g. "triangle1"
  aligned_buffer<std::byte> bytes;  ///< the blocks, each a multiple of 16 bytes
};

/// A way of storing a leaf's triangles: a block type, how many blocks `n` triangles take, and
/// how to fill them from the mesh. Chapter 2 has one (Triangle1Layout); chapter 6 adds more.
template <class L>
concept LeafLayout = requires(const TriangleMesh& mesh, std::span<const uint32_t> prims,
                              typename L::Block* out) {
  { L::kName } -> std::convertible_to<std::string_view>;
  { L::block_count(size_t{}) } -> std::same_as<size_t>;
  L::pack(mesh, prims, out);
} && sizeof(typename L::Block) % 16 == 0;

/// How many blocks of layout L a leaf of `n` triangles takes. Throws std::invalid_argument
/// when that is more than a leaf reference can count (kMaxLeafBlocks).
template <LeafLayout L>
size_t blocks_for_leaf(size_t n) {
  const size_t blocks = L::block_count(n);
  if (blocks > kMaxLeafBlocks)
    throw std::invalid_argument(
        std::string("a leaf of ") + std::to_string(n) + " triangles needs " +
        std::to_string(blocks) + " " + std::string(L::kName) + " blocks, more than the " +
        std::to_string(kMaxLeafBlocks) + " a leaf can hold: build with a smaller leaf size");
  return blocks;
}

/// Packs the blocks of one leaf holding triangles `prims` at byte `offset` of `leaves`, which
/// holds them already, and returns its reference. The bytes were sized but not written (many
/// threads pack at once, and zeroing them all first was a pass on one thread); they are zeroed
/// here, leaf by leaf, so that a layout's unused bytes are the same in every build.
template <LeafLayout L>
NodeRef pack_leaf(LeafBlocks& leaves, size_t offset, const TriangleMesh& mesh,
                  std::span<const uint32_t> prims) {
  const size_t blocks = blocks_for_leaf<L>(prims.size());
  if (blocks == 0) return kEmptyLeaf;
  std::byte* out = leaves.bytes.data() + offset;
  std::memset(out, 0, blocks * sizeof(typename L::Block));
  L::pack(mesh, prims, reinterpret_cast<typename L::Block*>(out));
  return make_leaf_ref(offset, uint32_t(blocks));
}

/// Appends the blocks of one leaf holding triangles `prims` and returns its reference. Throws
/// std::invalid_argument when the leaf needs more than kMaxLeafBlocks blocks.
template <LeafLayout L>
NodeRef append_leaf(LeafBlocks& leaves, const TriangleMesh& mesh, std::span<const uint32_t> prims) {
  const size_t offset = leaves.bytes.size();
  leaves.bytes.resize(offset + blocks_for_leaf<L>(prims.size()) * sizeof(typename L::Block));
  return pack_leaf<L>(leaves, offset, mesh, prims);
}

/// Throws std::invalid_argument unless the leaves are stored in the layout a kernel reads.
inline void require_layout(const LeafBlocks& leaves, std::string_view kernel_layout) {
  if (leaves.layout != kernel_layout)
    throw std::invalid_argument("this kernel reads " + std::string(kernel_layout) +
                                " leaves, but the structure holds " + leaves.layout + " leaves");
}

/// Throws std::invalid_argument unless a kernel is given as many results as rays.
inline void require_same_size(size_t rays, size_t results) {
  if (rays != results)
    throw std::invalid_argument(std::to_string(rays) + " rays but room for " +
                                std::to_string(results) + " results");
}

}  // namespace rtk
