/// \file
/// Single-ray traversal of a BVH2, generic over the leaf intersector (see leaf_intersector.h
/// for what a leaf intersector provides).
#pragma once

#ifndef RTK_ISA
#error "bvh2_traverser.h belongs to kernel sources compiled once per ISA"
#endif

#include <cmath>
#include <limits>
#include <span>

#include "01_base/platform.h"
#include "01_base/simd.h"
#include "02_bvh2/bvh2.h"
#include "02_bvh2/conservative_exit.h"

namespace rtk::RTK_ISA {

/// The ray as the BVH2 box test sees it, in rows that line up with a node's rows.
struct Bvh2Ray {
  vfloat<4> org_x, org_y, org_z;
  /// 1/dir, negated in the two upper lanes: a node row times it gives entry distances in lanes
  /// 0-1 and negated exit distances in lanes 2-3, so one max chain finds both.
  vfloat<4> rdir_x, rdir_y, rdir_z;
  /// (tnear, tnear, -tfar, -tfar): the ray's own interval in the same form.
  vfloat<4> limits;
};

// [ch02-row]
/// A node row with the halves swapped where the ray runs toward -axis, so that its lanes are
/// (near left, near right, far left, far right) for this ray: a compile-time choice, because
/// the traversal loop is compiled once per octant of ray directions.
template <bool kNegative>
RTK_INLINE vfloat<4> near_far_row(const float* row) {
  const vfloat<4> r = vfloat<4>::load(row);
  if constexpr (kNegative) return shuffle<2, 3, 0, 1>(r);
  else return r;
}
// [ch02-row]

// [ch02-box-test]
/// Tests the ray against both children of a node. Returns the hit mask (bit 0 left, bit 1
/// right) and leaves the children's entry distances in lanes 0 and 1 of `dist`.
template <bool kNegX, bool kNegY, bool kNegZ>
RTK_INLINE uint32_t intersect_node2(const Node2& node, const Bvh2Ray& ray, vfloat<4>& dist) {
  const vfloat<4> tx = (near_far_row<kNegX>(node.x) - ray.org_x) * ray.rdir_x;
  const vfloat<4> ty = (near_far_row<kNegY>(node.y) - ray.org_y) * ray.rdir_y;
  const vfloat<4> tz = (near_far_row<kNegZ>(node.z) - ray.org_z) * ray.rdir_z;
  // The ray's limits come last: where a slab gives 0 * inf = NaN (a ray in the plane of a
  // face), max returns its second operand and the NaN drops out instead of rejecting the box.
  dist = max(max(tx, ty), max(tz, ray.limits));
  // Lanes 2-3 hold minus the exit distances: move them under lanes 0-1, widen them by the
  // rounding bound (conservative_exit.h), and compare.
  const vfloat<4> exit = widen_exit(-shuffle<2, 3, 2, 3>(dist));
  return movemask(dist <= exit) & 3;
}
// [ch02-box-test]

/// Traces one valid ray whose direction lies in the octant (kNegX, kNegY, kNegZ). For a closest
/// hit (kOcclusion false) it returns whether a hit was found and writes it to `hit`; for
/// occlusion it returns whether anything blocks the ray.
template <class Leaf, bool kOcclusion, bool kNegX, bool kNegY, bool kNegZ>
bool traverse_bvh2(const BVH2& bvh, const Ray& ray, const Vec3f& rdir, Hit& hit) {
  const typename Leaf::Precalc pre(ray);
  // Setup: the ray in node-row form. A tnear of -inf is clamped so that the limits never
  // make inf - inf.
  const float tnear = ray.tnear > -std::numeric_limits<float>::max() ? ray.tnear : -std::numeric_limits<float>::max();
  float tfar = ray.tfar;
  Bvh2Ray r;
  r.org_x = vfloat<4>(ray.org.x), r.org_y = vfloat<4>(ray.org.y), r.org_z = vfloat<4>(ray.org.z);
  auto signed_row = [](float s) {
    alignas(16) const float row[4] = {s, s, -s, -s};
    return vfloat<4>::load(row);
  };
  r.rdir_x = signed_row(rdir.x), r.rdir_y = signed_row(rdir.y), r.rdir_z = signed_row(rdir.z);
  auto make_limits = [tnear](float far) {
    alignas(16) const float row[4] = {tnear, tnear, -far, -far};
    return vfloat<4>::load(row);
  };
  r.limits = make_limits(tfar);
  float cull = conservative_tfar(tfar);  // pushed entries beyond it are skipped

  struct Entry {
    NodeRef ref;
    float dist;  ///< the entry distance when pushed: popped entries beyond tfar are skipped
  };
  Entry stack[kBvh2StackSize];
  Entry* sp = stack;
  *sp++ = {kTerminal, -std::numeric_limits<float>::infinity()};
  const std::byte* leaf_bytes = bvh.leaves.bytes.data();
  bool found = false;

  // [ch02-traverse]
  NodeRef cur = bvh.root;
  for (;;) {
    // Descend: follow one child without touching the stack while there is one to follow.
    while (!is_leaf(cur)) {
      const Node2& node = bvh.node(cur);
      vfloat<4> dist;
      const uint32_t mask = intersect_node2<kNegX, kNegY, kNegZ>(node, r, dist);
      if (mask == 0) goto pop;
      if (mask != 3) {
        cur = node.children[mask >> 1];
        continue;
      }
      // Both children: go to the nearer, push the farther with its entry distance.
      alignas(16) float d[4];
      dist.store(d);
      const int first = d[1] < d[0] ? 1 : 0;
      *sp++ = {node.children[1 - first], d[1 - first]};
      cur = node.children[first];
    }
    if (cur == kTerminal) break;
    // Leaf: the intersector tests its blocks and, for a closest hit, shortens the ray.
    {
      const auto* blocks = reinterpret_cast<const typename Leaf::Block*>(leaf_bytes + leaf_offset(cur));
      if constexpr (kOcclusion) {
        if (Leaf::occluded(pre, ray, blocks, leaf_blocks(cur), tfar)) return true;
      } else if (Leaf::intersect(pre, ray, blocks, leaf_blocks(cur), hit, tfar)) {
        found = true;
        r.limits = make_limits(tfar);
        cull = conservative_tfar(tfar);
      }
    }
  pop:
    // Pop, skipping entries whose box begins beyond the closest hit found since their push.
    // The bottom entry's distance is -inf: it is never skipped, and it ends the loop.
    do --sp;
    while (sp->dist > cull);
    cur = sp->ref;
  }
  // [ch02-traverse]
  return found;
}

/// Traces one ray of any kind: invalid rays miss without traversal; valid ones run the loop
/// compiled for their octant.
template <class Leaf, bool kOcclusion>
RTK_INLINE bool trace_bvh2(const BVH2& bvh, const Ray& ray, Hit& hit) {
  if (!is_valid(ray)) return false;
  // 1/(+-0) = +-inf keeps the sign of a zero component, so the octant and the planes agree.
  const Vec3f rdir{1.0f / ray.dir.x, 1.0f / ray.dir.y, 1.0f / ray.dir.z};
  const int octant = (std::signbit(rdir.x) ? 1 : 0) | (std::signbit(rdir.y) ? 2 : 0) |
                     (std::signbit(rdir.z) ? 4 : 0);
  switch (octant) {
    case 0: return traverse_bvh2<Leaf, kOcclusion, false, false, false>(bvh, ray, rdir, hit);
    case 1: return traverse_bvh2<Leaf, kOcclusion, true, false, false>(bvh, ray, rdir, hit);
    case 2: return traverse_bvh2<Leaf, kOcclusion, false, true, false>(bvh, ray, rdir, hit);
    case 3: return traverse_bvh2<Leaf, kOcclusion, true, true, false>(bvh, ray, rdir, hit);
    case 4: return traverse_bvh2<Leaf, kOcclusion, false, false, true>(bvh, ray, rdir, hit);
    case 5: return traverse_bvh2<Leaf, kOcclusion, true, false, true>(bvh, ray, rdir, hit);
    case 6: return traverse_bvh2<Leaf, kOcclusion, false, true, true>(bvh, ray, rdir, hit);
    default: return traverse_bvh2<Leaf, kOcclusion, true, true, true>(bvh, ray, rdir, hit);
  }
}

// [ch02-batch-kernels]
/// The batch kernels of a BVH2 whose leaves Leaf reads, in the form every structure hands out
/// (trace_kernels.h): `structure` is the BVH2. Chapter 2 makes its kernels with
/// Triangle1Moeller; chapters 6 and 7 give the same loop every layout and test.
template <class Leaf>
void intersect_bvh2_batch(const void* structure, std::span<const Ray> rays, std::span<Hit> hits) {
  require_same_size(rays.size(), hits.size());
  const BVH2& bvh = *static_cast<const BVH2*>(structure);
  for (size_t i = 0; i < rays.size(); ++i) {
    Hit hit;
    trace_bvh2<Leaf, false>(bvh, rays[i], hit);
    hits[i] = hit;
  }
}
template <class Leaf>
void occluded_bvh2_batch(const void* structure, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  require_same_size(rays.size(), occluded.size());
  const BVH2& bvh = *static_cast<const BVH2*>(structure);
  Hit unused;
  for (size_t i = 0; i < rays.size(); ++i) occluded[i] = trace_bvh2<Leaf, true>(bvh, rays[i], unused) ? 1 : 0;
}
template <class Leaf>
constexpr TraceKernels bvh2_batch_kernels() {
  return {&intersect_bvh2_batch<Leaf>, &occluded_bvh2_batch<Leaf>};
}
// [ch02-batch-kernels]

}  // namespace rtk::RTK_ISA
