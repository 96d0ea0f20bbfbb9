/// \file
/// Leaf intersectors: what a traversal calls when it reaches a leaf. One template, written once
/// here, turns a leaf layout (how a leaf's triangles are stored) and a ray/triangle test (how
/// one ray meets K triangles) into the policy every traversal of the book is generic over.
///
/// A leaf intersector is a class with
/// - `Block` and `kLayout`: the block type it reads and the name of its layout (LeafBlocks);
/// - `Precalc`: what it computes once per ray (constructed from the Ray);
/// - `intersect(pre, ray, blocks, count, hit, tfar)`: the closest hit among `count` blocks with
///   t in [ray.tnear, tfar], by the rule of closest_in_block() below; it writes it to `hit`,
///   lowers `tfar` to its t and returns true, or returns false and touches nothing;
/// - `occluded(pre, ray, blocks, count, tfar)`: whether any hit lies in [ray.tnear, tfar].
/// Chapter 2 has one layout (Triangle1) and one test (Möller-Trumbore); chapter 6 adds layouts
/// by adding loaders for their blocks, chapter 7 adds tests, and nothing here changes.
/// Per-ISA template: include from kernel sources only.
#pragma once

#ifndef RTK_ISA
#error "leaf_intersector.h belongs to kernel sources compiled once per ISA"
#endif

#include <cstdint>
#include <limits>
#include <string_view>
#include <type_traits>

#include "01_base/platform.h"
#include "01_base/ray.h"
#include "01_base/simd.h"
#include "02_bvh2/moeller.h"
#include "02_bvh2/triangle1.h"

namespace rtk::RTK_ISA {

// [ch02-load-triangle1]
/// Chapter 2's Triangle1 as Möller-Trumbore's inputs: v0 and the edges are stored; the normal
/// is computed per ray, with the same float operations as a precomputing layout would use.
RTK_INLINE void load_moeller(const Triangle1& b, Vec3v<1>& v0, Vec3v<1>& e1, Vec3v<1>& e2, Vec3v<1>& ng) {
  v0 = Vec3v<1>(b.v0), e1 = Vec3v<1>(b.e1), e2 = Vec3v<1>(b.e2);
  ng = cross(e1, e2);
}
// [ch02-load-triangle1]

/// The primID of a block's lane: every layout's block has a `prim` member, one number for a
/// block of one triangle, an array for a block of several.
template <class Block>
RTK_INLINE uint32_t block_prim(const Block& b, int lane) {
  if constexpr (std::is_array_v<decltype(Block::prim)>) return b.prim[lane];
  else return b.prim;
}

// [ch02-closest-rule]
/// Whether a hit at distance t on triangle `prim` replaces `hit`: a smaller t wins, and at
/// equal t the lower primID (the same triangle again changes nothing).
RTK_INLINE bool improves_on(float t, uint32_t prim, const Hit& hit) {
  return !hit.found() || t < hit.t || (t == hit.t && prim <= hit.prim);
}

/// The closest of a block's valid lanes, and whether it improves on `hit`: a smaller t wins,
/// and at equal t the lower primID. The rule decides the same way whatever order the blocks,
/// lanes and leaves are met in, so every layout, block width, node width and build finds the
/// same hit for the same test (a tie at equal t is common: a ray through a shared edge hits
/// both triangles at once). Lanes with t above tfar are not in `valid`.
template <int K, class Block>
RTK_INLINE bool closest_in_block(vbool<K> valid, const TriangleHitsK<K>& h, const Block& block, Hit& hit) {
  const vfloat<K> t = select(valid, h.t, vfloat<K>(std::numeric_limits<float>::infinity()));
  const float nearest = reduce_min(t);
  uint32_t lanes = movemask(valid & (t == vfloat<K>(nearest)));
  int lane = pop_lowest_bit(lanes);
  uint32_t prim = block_prim(block, lane);
  for (const int other : set_bits(lanes)) {  // rare: equal t within one block
    const uint32_t p = block_prim(block, other);
    if (p < prim) lane = other, prim = p;
  }
  if (!improves_on(nearest, prim, hit)) return false;
  hit = Hit{nearest, h.u[lane], h.v[lane], prim};
  return true;
}
// [ch02-closest-rule]

// [ch02-leaf]
/// Triangles per block: a layout without a kWidth member has one triangle per block.
template <class L>
constexpr int block_width() {
  if constexpr (requires { L::kWidth; }) return L::kWidth;
  else return 1;
}

/// A leaf policy for blocks of layout L tested with Test, K = the block's triangles at a time.
/// kPrecomputed selects the precomputed form of Möller-Trumbore (v0, e1, e2, Ng: the layouts
/// that store those) over the vertex form (p0, p1, p2) that every test has.
template <class L, class Test, bool kPrecomputed = false>
struct LeafIntersector {
  using Block = typename L::Block;
  static constexpr int K = block_width<L>();
  static constexpr std::string_view kLayout = L::kName;
  using Precalc = typename Test::template Precalc<K>;

  /// Tests one block; the mask of lanes hit in [tnear, tfar].
  static RTK_INLINE vbool<K> test(const Precalc& pre, const Block& block, float tfar, TriangleHitsK<K>& h) {
    if constexpr (kPrecomputed) {
      Vec3v<K> v0, e1, e2, ng;
      load_moeller(block, v0, e1, e2, ng);
      return Test::intersect(pre, vfloat<K>(tfar), v0, e1, e2, ng, h);
    } else {
      Vec3v<K> p0, p1, p2;
      load_vertices(block, p0, p1, p2);
      return Test::intersect(pre, vfloat<K>(tfar), p0, p1, p2, h);
    }
  }

  /// The closest hit among `count` blocks in [ray.tnear, tfar]; lowers tfar to it.
  static RTK_INLINE bool intersect(const Precalc& pre, const Ray&, const Block* blocks, uint32_t count,
                                   Hit& hit, float& tfar) {
    bool found = false;
    for (uint32_t b = 0; b < count; ++b) {
      TriangleHitsK<K> h{};  // a test may leave the lanes it rejects early unwritten
      const vbool<K> valid = test(pre, blocks[b], tfar, h);
      if (none(valid) || !closest_in_block(valid, h, blocks[b], hit)) continue;
      tfar = hit.t;
      found = true;
    }
    return found;
  }

  /// Whether any of `count` blocks is hit in [ray.tnear, tfar].
  static RTK_INLINE bool occluded(const Precalc& pre, const Ray&, const Block* blocks, uint32_t count,
                                  float tfar) {
    for (uint32_t b = 0; b < count; ++b) {
      TriangleHitsK<K> h;
      if (any(test(pre, blocks[b], tfar, h))) return true;
    }
    return false;
  }
};
// [ch02-leaf]

/// Chapter 2's leaves: Triangle1 blocks, Möller-Trumbore on the stored edges.
using Triangle1Moeller = LeafIntersector<Triangle1Layout, MoellerTrumbore, true>;

}  // namespace rtk::RTK_ISA
