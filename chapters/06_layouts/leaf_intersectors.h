/// \file
/// Leaf intersectors: a layout's blocks read as K triangles at once and handed to one of
/// chapter 7's tests. Each is a policy for the traversals of chapters 2 and 3 (see
/// 02_bvh2/triangle1_intersector.h for the interface: Block, kLayout, Precalc, intersect,
/// occluded). Per-ISA template: include from kernel sources only.
#pragma once

#ifndef RTK_ISA
#error "leaf_intersectors.h belongs to kernel sources compiled once per ISA"
#endif

#include <bit>
#include <cstdint>
#include <limits>
#include <string_view>

#include "01_base/platform.h"
#include "01_base/ray.h"
#include "01_base/simd.h"
#include "02_bvh2/triangle1.h"
#include "06_layouts/triangle_i.h"
#include "06_layouts/triangle_m.h"
#include "06_layouts/triangle_v.h"
#include "07_intersectors/moeller.h"
#include "07_intersectors/pluecker.h"
#include "07_intersectors/watertight.h"

namespace rtk::RTK_ISA {

// [ch06-load-blocks]
// How each layout's block becomes K triangles in registers. The precomputed blocks give
// Möller-Trumbore's (v0, e1, e2, Ng) with no arithmetic; triangle1 keeps no normal and
// computes it; the vertex blocks load, the indexed blocks gather through their indices.

/// Chapter 2's Triangle1: v0 and the edges are stored, the normal is computed per ray.
RTK_INLINE void load_moeller(const Triangle1& b, Vec3v<1>& v0, Vec3v<1>& e1, Vec3v<1>& e2, Vec3v<1>& ng) {
  v0 = Vec3v<1>(b.v0), e1 = Vec3v<1>(b.e1), e2 = Vec3v<1>(b.e2);
  ng = cross(e1, e2);
}
/// triangle4 and triangle8: four aligned rows of M floats per vector.
template <int M>
RTK_INLINE void load_moeller(const TriangleM<M>& b, Vec3v<M>& v0, Vec3v<M>& e1, Vec3v<M>& e2, Vec3v<M>& ng) {
  v0 = Vec3v<M>::load(b.v0[0], b.v0[1], b.v0[2], 0);
  e1 = Vec3v<M>::load(b.e1[0], b.e1[1], b.e1[2], 0);
  e2 = Vec3v<M>::load(b.e2[0], b.e2[1], b.e2[2], 0);
  ng = Vec3v<M>::load(b.Ng[0], b.Ng[1], b.Ng[2], 0);
}

RTK_INLINE void load_vertices(const Triangle1v& b, Vec3v<1>& p0, Vec3v<1>& p1, Vec3v<1>& p2) {
  p0 = Vec3v<1>(b.p0), p1 = Vec3v<1>(b.p1), p2 = Vec3v<1>(b.p2);
}
template <int M>
RTK_INLINE void load_vertices(const TriangleMv<M>& b, Vec3v<M>& p0, Vec3v<M>& p1, Vec3v<M>& p2) {
  p0 = Vec3v<M>::load(b.p[0][0], b.p[0][1], b.p[0][2], 0);
  p1 = Vec3v<M>::load(b.p[1][0], b.p[1][1], b.p[1][2], 0);
  p2 = Vec3v<M>::load(b.p[2][0], b.p[2][1], b.p[2][2], 0);
}
RTK_INLINE void load_vertices(const Triangle1i& b, Vec3v<1>& p0, Vec3v<1>& p1, Vec3v<1>& p2) {
  p0 = Vec3v<1>(b.vertices[b.v[0]]), p1 = Vec3v<1>(b.vertices[b.v[1]]), p2 = Vec3v<1>(b.vertices[b.v[2]]);
}
/// triangle4i: each component of each vertex is one gather at float offset 3 v + axis.
template <int M>
RTK_INLINE void load_vertices(const TriangleMi<M>& b, Vec3v<M>& p0, Vec3v<M>& p1, Vec3v<M>& p2) {
  const float* base = &b.vertices[0].x;
  Vec3v<M>* out[3] = {&p0, &p1, &p2};
  for (int k = 0; k < 3; ++k) {
    const vint<M> offset = vint<M>::load(b.v[k]) * vint<M>(3);
    *out[k] = {vfloat<M>::gather(base, offset), vfloat<M>::gather(base, offset + vint<M>(1)),
               vfloat<M>::gather(base, offset + vint<M>(2))};
  }
}
// [ch06-load-blocks]

RTK_INLINE uint32_t block_prim(const Triangle1& b, int) { return b.prim; }
RTK_INLINE uint32_t block_prim(const Triangle1v& b, int) { return b.prim; }
RTK_INLINE uint32_t block_prim(const Triangle1i& b, int) { return b.prim; }
template <int M> RTK_INLINE uint32_t block_prim(const TriangleM<M>& b, int lane) { return b.prim[lane]; }
template <int M> RTK_INLINE uint32_t block_prim(const TriangleMv<M>& b, int lane) { return b.prim[lane]; }
template <int M> RTK_INLINE uint32_t block_prim(const TriangleMi<M>& b, int lane) { return b.prim[lane]; }

/// The nearest of the valid lanes, the highest one among equals: lanes hold a leaf's
/// triangles in order, and a later triangle at the same distance wins, as it does from one
/// block to the next (the traversal's t <= tfar). So every block width finds the same hit.
template <int K>
RTK_INLINE int nearest_lane(vbool<K> valid, vfloat<K> t) {
  const vfloat<K> masked = select(valid, t, vfloat<K>(std::numeric_limits<float>::infinity()));
  const uint32_t nearest = movemask(valid & (masked == vfloat<K>(reduce_min(masked))));
  return 31 - std::countl_zero(nearest);
}

// [ch06-leaf]
/// Triangles per block: chapter 2's Triangle1Layout predates the kWidth member.
template <class L> inline constexpr int kBlockWidth = L::kWidth;
template <> inline constexpr int kBlockWidth<Triangle1Layout> = 1;

/// A leaf policy for blocks of layout L tested with Intersector, K triangles of a block at a
/// time. kPrecomputed selects Möller-Trumbore's precomputed form (v0, e1, e2, Ng) over the
/// vertex form.
template <class L, class Intersector, bool kPrecomputed = false>
struct LeafIntersector {
  using Block = typename L::Block;
  static constexpr int K = kBlockWidth<L>;
  static constexpr std::string_view kLayout = L::kName;
  using Precalc = typename Intersector::template Precalc<K>;

  /// Tests one block; the mask of lanes hit in [tnear, tfar].
  static RTK_INLINE vbool<K> test(const Precalc& pre, const Block& block, float tfar, TriangleHitsK<K>& h) {
    if constexpr (kPrecomputed) {
      Vec3v<K> v0, e1, e2, ng;
      load_moeller(block, v0, e1, e2, ng);
      return Intersector::intersect(pre, vfloat<K>(tfar), v0, e1, e2, ng, h);
    } else {
      Vec3v<K> p0, p1, p2;
      load_vertices(block, p0, p1, p2);
      return Intersector::intersect(pre, vfloat<K>(tfar), p0, p1, p2, h);
    }
  }

  /// The closest hit among `count` blocks in [ray.tnear, tfar]; lowers tfar to it.
  static RTK_INLINE bool intersect(const Precalc& pre, const Ray&, const Block* blocks, uint32_t count,
                                   Hit& hit, float& tfar) {
    bool found = false;
    for (uint32_t b = 0; b < count; ++b) {
      TriangleHitsK<K> h;
      const vbool<K> valid = test(pre, blocks[b], tfar, h);
      if (none(valid)) continue;
      const int lane = nearest_lane(valid, h.t);
      hit = Hit{h.t[lane], h.u[lane], h.v[lane], block_prim(blocks[b], lane)};
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
// [ch06-leaf]

}  // namespace rtk::RTK_ISA
