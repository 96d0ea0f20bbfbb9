/// \file
/// Single-ray traversal of a BVH4MB/BVH8MB: chapter 3's traversal with all its tricks, where
/// the box test interpolates each child's planes at the ray's time and the leaves interpolate
/// their vertices before the triangle test. Per-ISA template: include from kernel sources only.
#pragma once

#ifndef RTK_ISA
#error "bvhmb_traverser.h belongs to kernel sources compiled once per ISA"
#endif

#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>

#include "01_base/platform.h"
#include "01_base/simd.h"
#include "03_bvh4/bvhn_traverser.h"
#include "02_bvh2/leaf_intersector.h"
#include "06_layouts/layout_loads.h"
#include "07_intersectors/pluecker.h"
#include "07_intersectors/watertight.h"
#include "08_motion/bvh4mb.h"

namespace rtk::RTK_ISA {

/// Tests the ray at time `time` (broadcast) against the N moving children of a node. Returns
/// the hit mask and leaves each child's entry distance in `dist`.
template <int N>
RTK_INLINE uint32_t intersect_node_mb(const NodeMB<N>& node, const BvhNRay<N>& r, vfloat<N> time, vfloat<N>& dist) {
  // [ch08-box-at-time]
  // The motion rows sit six rows after the box rows, so the near and far offsets that chapter 3
  // chose by the direction's signs find both: the plane at time t is row + t * row[6].
  constexpr size_t kMotion = 6 * sizeof(float) * N;
  const char* base = reinterpret_cast<const char*>(&node);
  auto plane = [base, time](size_t offset) {
    const vfloat<N> p0 = vfloat<N>::load(reinterpret_cast<const float*>(base + offset));
    const vfloat<N> dp = vfloat<N>::load(reinterpret_cast<const float*>(base + offset + kMotion));
    return p0 + time * dp;
  };
  const vfloat<N> nx = (r.org_x - plane(r.near_x)) * r.neg_rdir_x;
  const vfloat<N> ny = (r.org_y - plane(r.near_y)) * r.neg_rdir_y;
  const vfloat<N> nz = (r.org_z - plane(r.near_z)) * r.neg_rdir_z;
  const vfloat<N> fx = (r.org_x - plane(r.far_x)) * r.neg_rdir_x;
  const vfloat<N> fy = (r.org_y - plane(r.far_y)) * r.neg_rdir_y;
  const vfloat<N> fz = (r.org_z - plane(r.far_z)) * r.neg_rdir_z;
  // [ch08-box-at-time]
  dist = max(max(nx, ny), max(nz, r.tnear));
  const vfloat<N> exit = min(widen_exit(min(min(fx, fy), fz)), r.tfar);  // chapter 2's widening
  return movemask(dist <= exit);
}

/// What a motion leaf needs besides its blocks: the intersector's view of the ray, the ray's
/// time, and the mesh's motion arrays.
template <class Intersector, int M>
struct MotionPrecalc {
  typename Intersector::template Precalc<M> ray;
  vfloat<M> time;
  const float* motion;   ///< the motion vectors as floats, three per entry
  const uint32_t* slot;  ///< sparse storage: each vertex's entry in `motion`; dense: null

  MotionPrecalc(const Ray& r, const MotionMesh& mesh)
      : ray(r), time(r.time), motion(reinterpret_cast<const float*>(mesh.motion.data())), slot(mesh.slot.empty() ? nullptr : mesh.slot.data()) {}
};

// [ch08-leaf]
/// A triangle4i leaf in motion: the block's vertices at time 0 are gathered through its
/// indices (chapter 6), their motion vectors through the same indices (dense) or through each
/// vertex's slot (sparse), and every vertex is moved to the ray's time before Intersector tests
/// the four triangles.
template <MotionStorage S, class Intersector>
struct MotionLeaf {
  static constexpr int M = 4;
  using Block = TriangleMi<M>;
  using Precalc = MotionPrecalc<Intersector, M>;

  /// Tests the four triangles of one block at the ray's time; the mask of lanes hit in
  /// [tnear, tfar].
  static RTK_INLINE vbool<M> test(const Precalc& pre, const Block& block, float tfar, TriangleHitsK<M>& h) {
    Vec3v<M> p[3];
    load_vertices(block, p[0], p[1], p[2]);
    for (int k = 0; k < 3; ++k) {
      vint<M> entry = vint<M>::load(block.v[k]);
      if constexpr (S == MotionStorage::sparse) {
        alignas(16) int32_t slots[M];
        for (int i = 0; i < M; ++i) slots[i] = int32_t(pre.slot[block.v[k][i]]);
        entry = vint<M>::load(slots);
      }
      const vint<M> offset = entry * vint<M>(3);
      const vfloat<M> dx = vfloat<M>::gather(pre.motion, offset);
      const vfloat<M> dy = vfloat<M>::gather(pre.motion, offset + vint<M>(1));
      const vfloat<M> dz = vfloat<M>::gather(pre.motion, offset + vint<M>(2));
      // The same two roundings per component as vertex_at().
      p[k] = {p[k].x + pre.time * dx, p[k].y + pre.time * dy, p[k].z + pre.time * dz};
    }
    return Intersector::intersect(pre.ray, vfloat<M>(tfar), p[0], p[1], p[2], h);
  }
  // [ch08-leaf]

  /// The closest hit among `count` blocks in [tnear, tfar]; lowers tfar to it.
  static RTK_INLINE bool intersect(const Precalc& pre, const Block* blocks, uint32_t count, Hit& hit, float& tfar) {
    bool found = false;
    for (uint32_t b = 0; b < count; ++b) {
      TriangleHitsK<M> h{};  // a test may leave the lanes it rejects early unwritten
      const vbool<M> valid = test(pre, blocks[b], tfar, h);
      if (none(valid) || !closest_in_block(valid, h, blocks[b], hit)) continue;
      tfar = hit.t;
      found = true;
    }
    return found;
  }

  /// Whether any of `count` blocks is hit in [tnear, tfar].
  static RTK_INLINE bool occluded(const Precalc& pre, const Block* blocks, uint32_t count, float tfar) {
    for (uint32_t b = 0; b < count; ++b) {
      TriangleHitsK<M> h;
      if (any(test(pre, blocks[b], tfar, h))) return true;
    }
    return false;
  }
};

/// Traces one motion ray through a BVHMB with chapter 3's tricks (near/far planes by sign,
/// early pop, the 1- and 2-hit paths, sorted push, cull at pop, prefetching, shadow rays in
/// stored order). Returns whether a hit was
/// found (closest hit: written to `hit`) or whether anything blocks (occlusion).
template <int N, class Leaf, bool kOcclusion>
bool traverse_bvhmb(const BVHMB<N>& bvh, const Ray& ray, Hit& hit) {
  const typename Leaf::Precalc pre(ray, bvh.mesh);
  BvhNRay<N> r = make_bvhn_ray<N>(ray);
  const vfloat<N> time(ray.time);
  float tfar = ray.tfar;
  float cull = conservative_tfar(tfar);

  BvhStackEntry stack[kBvhMbMaxDepth * (N - 1) + 1 + N];  // N spare, as kBvhStackSize
  BvhStackEntry* sp = stack;
  *sp++ = {kTerminal, -std::numeric_limits<float>::infinity()};
  const std::byte* leaf_bytes = bvh.leaves.bytes.data();
  bool found = false;

  NodeRef cur = bvh.root;
  for (;;) {
    while (!is_leaf(cur)) {
      const NodeMB<N>& node = bvh.node(cur);
      const BvhStackEntry next = sp[-1];
      vfloat<N> dist;
      uint32_t mask = intersect_node_mb<N>(node, r, time, dist);
      // 0 children hit: the next entry is already read (early pop).
      if (mask == 0) {
        --sp;
        if (!kOcclusion && next.dist > cull) goto pop;
        cur = next.ref;
        continue;
      }
      // The hit children are prefetched, and chapter 3 chooses the next one and what to push
      // (shadow rays in stored order, closest hits nearest first), with all its tricks on.
      for (int i : set_bits(mask)) prefetch_child(bvh, leaf_bytes, node.children[i]);
      cur = next_child<N, Tricks{}, kOcclusion>(node.children, mask, dist, sp);
    }
    if (cur == kTerminal) break;
    {
      const auto* blocks = reinterpret_cast<const typename Leaf::Block*>(leaf_bytes + leaf_offset(cur));
      const uint32_t count = leaf_blocks(cur);
      if constexpr (kOcclusion) {
        if (Leaf::occluded(pre, blocks, count, tfar)) return true;
      } else if (Leaf::intersect(pre, blocks, count, hit, tfar)) {
        found = true;
        shorten(r, tfar);
        cull = conservative_tfar(tfar);
      }
    }
  pop:
    --sp;
    if constexpr (!kOcclusion)
      while (sp->dist > cull) --sp;
    cur = sp->ref;
  }
  return found;
}

/// Closest hits of rays[i] into hits[i] through the BVHMB<N> `structure`; rays that are not
/// motion rays miss.
template <int N, class Leaf>
void intersect_mb(const void* structure, std::span<const Ray> rays, std::span<Hit> hits) {
  require_same_size(rays.size(), hits.size());
  const BVHMB<N>& bvh = *static_cast<const BVHMB<N>*>(structure);
  for (size_t i = 0; i < rays.size(); ++i) {
    Hit hit;
    if (is_valid_motion_ray(rays[i])) traverse_bvhmb<N, Leaf, false>(bvh, rays[i], hit);
    hits[i] = hit;
  }
}

/// Occlusion of rays[i] into occluded[i]; rays that are not motion rays are not occluded.
template <int N, class Leaf>
void occluded_mb(const void* structure, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  require_same_size(rays.size(), occluded.size());
  const BVHMB<N>& bvh = *static_cast<const BVHMB<N>*>(structure);
  Hit unused;
  for (size_t i = 0; i < rays.size(); ++i)
    occluded[i] = is_valid_motion_ray(rays[i]) && traverse_bvhmb<N, Leaf, true>(bvh, rays[i], unused) ? 1 : 0;
}

/// The batch kernels of a BVHMB<N> whose leaves Leaf reads.
template <int N, class Leaf>
constexpr TraceKernels motion_batch_kernels() {
  return {&intersect_mb<N, Leaf>, &occluded_mb<N, Leaf>};
}

}  // namespace rtk::RTK_ISA
