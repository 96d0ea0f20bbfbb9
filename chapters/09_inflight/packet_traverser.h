/// \file
/// Rays in packets: P rays of a batch (P the ISA's float width) traverse a BVH together, one
/// ray per SIMD lane, each node and leaf read once for all of them. Where the rays go the same
/// way (camera rays, shadow rays toward one light from neighbouring points) the packet does the
/// work of P single-ray traversals in the time of about one. Every lane computes what chapter 3's
/// traversal and chapter 2's Möller-Trumbore test compute for its ray, in the same operations,
/// and keeps the closest hit by the same order-free rule, so the answers are the single-ray
/// answers bit for bit. Per-ISA template: include from kernel sources only.
#pragma once

#ifndef RTK_ISA
#error "packet_traverser.h belongs to kernel sources compiled once per ISA"
#endif

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "01_base/platform.h"
#include "01_base/simd.h"
#include "02_bvh2/leaf_intersector.h"
#include "02_bvh2/moeller.h"
#include "03_bvh4/bvhn_traverser.h"
#include "06_layouts/triangle_m.h"

namespace rtk::RTK_ISA {

/// Rays per packet: one per lane of the widest float register.
inline constexpr int kPacketWidth = kNativeWidth;
/// A subtree that at most this many lanes enter is left to them one ray at a time: a packet's
/// box test costs N tests of P lanes, a ray's one test of N children (chapter 9 measures the
/// choice: an eighth of the packet on the real meshes, so two lanes of AVX-512's sixteen, one
/// of AVX2's eight, and none of SSE4's four).
inline constexpr int kAloneLanes = kPacketWidth / 8;

/// The octant of a direction (its three sign bits), which fixes the near and far planes of
/// every box for the ray.
RTK_INLINE uint32_t octant_of(const Vec3f& dir) {
  return uint32_t(std::signbit(dir.x)) | uint32_t(std::signbit(dir.y)) << 1 | uint32_t(std::signbit(dir.z)) << 2;
}

// [ch09-packet-ray]
/// P rays as the box and triangle tests see them, one per lane. Every lane holds exactly the
/// values chapter 3's BvhNRay and chapter 2's Precalc hold for its ray; the rays share their
/// octant, so the near and far rows of a node are the same for all. A lane without a ray (a
/// group's invalid rays are left out of its packet, so these are the lanes past its count) is
/// dead from the start: its interval is empty. What the box test reads and never changes is
/// kept apart (PacketBox), so that the traversal can hold it in registers.
template <int P>
struct PacketBox {
  vfloat<P> org_x, org_y, org_z;
  vfloat<P> neg_rdir_x, neg_rdir_y, neg_rdir_z;
  vfloat<P> tnear;  ///< tnear clamped to finite, as BvhNRay has it
  size_t near_x, near_y, near_z, far_x, far_y, far_z;
};

template <int P>
struct RayPacket {
  MoellerTrumbore::Precalc<P> pre;  ///< origins, directions and tnear as the test reads them
  PacketBox<P> box;     ///< what the box test reads, the same for the whole traversal
  vfloat<P> tfar;       ///< the closest hit so far (the ray's tfar before any)
  vfloat<P> box_tfar;   ///< tfar widened and kept finite (conservative_tfar)
  uint32_t live = 0;    ///< lanes still looking (occlusion: not yet blocked)

  explicit RayPacket(const Ray& first) : pre(first) {}
};

/// Loads `count` rays (at most P, all valid, all of octant `octant`) into a packet. The rays'
/// fields are gathered into lanes (the lanes past `count` repeat the first ray), and the values
/// are then made for all lanes at once (all but the widened tfar, chapter 2's function of one
/// float) by the operations make_bvhn_ray applies to one ray: an IEEE operation rounds the same
/// in a lane as in a scalar, so every lane holds its single ray's values bit for bit. (Copying
/// the fields into arrays first, each vector load then waiting on the scalar stores before it,
/// made SSE4's camera rays a fifth slower.)
template <int P, int N>
RTK_INLINE RayPacket<P> make_packet(const Ray* rays, int count, uint32_t octant) {
  constexpr float kInf = std::numeric_limits<float>::infinity(), kMax = std::numeric_limits<float>::max();
  // Lane i reads ray i (the first ray past `count`) field by field, a gather of nine floats
  // apart: a Ray is nine floats, org, tnear, dir, time, tfar.
  static_assert(sizeof(Ray) == 9 * sizeof(float) && offsetof(Ray, tfar) == 8 * sizeof(float));
  alignas(64) int32_t lane[P];
  for (int i = 0; i < P; ++i) lane[i] = i;
  const vint<P> index = vint<P>::load(lane);
  const vbool<P> live = index < vint<P>(count);
  const vint<P> first_float = select(live, index * vint<P>(9), vint<P>(0));
  const float* floats = reinterpret_cast<const float*>(rays);
  auto lanes = [&](int f) { return vfloat<P>::gather(floats + f, first_float); };
  const Vec3v<P> org(lanes(0), lanes(1), lanes(2)), dir(lanes(4), lanes(5), lanes(6));
  const vfloat<P> tnear = lanes(3), tfar = lanes(8);

  RayPacket<P> p(rays[0]);
  p.pre.org = org, p.pre.dir = dir;
  p.pre.tnear = select(live, tnear, vfloat<P>(kInf));
  const vfloat<P> one(1.0f);
  const Vec3v<P> rdir(one / dir.x, one / dir.y, one / dir.z);
  PacketBox<P>& box = p.box;
  box.org_x = org.x, box.org_y = org.y, box.org_z = org.z;
  box.neg_rdir_x = -rdir.x, box.neg_rdir_y = -rdir.y, box.neg_rdir_z = -rdir.z;
  // make_bvhn_ray's clamp of tnear and conservative_tfar, and empty intervals for the dead lanes.
  alignas(64) float box_tfar[P];
  for (int i = 0; i < P; ++i) box_tfar[i] = conservative_tfar(rays[i < count ? i : 0].tfar, true);
  box.tnear = select(live, select(tnear > vfloat<P>(-kMax), tnear, vfloat<P>(-kMax)), vfloat<P>(kInf));
  p.tfar = select(live, tfar, vfloat<P>(-kInf));
  p.box_tfar = select(live, vfloat<P>::load(box_tfar), vfloat<P>(-kMax));
  p.live = count >= 32 ? ~0u : (1u << count) - 1;
  // Chapter 3's rows: N floats each, the two rows of an axis adjacent, lower first.
  constexpr size_t kRow = sizeof(float) * N;
  auto near_row = [](int axis, bool negative) { return size_t(2 * axis) * kRow + (negative ? kRow : 0); };
  box.near_x = near_row(0, octant & 1), box.near_y = near_row(1, octant & 2), box.near_z = near_row(2, octant & 4);
  box.far_x = box.near_x ^ kRow, box.far_y = box.near_y ^ kRow, box.far_z = box.near_z ^ kRow;
  return p;
}
// [ch09-packet-ray]

// [ch09-packet-node]
/// Tests the packet against child `c` of a node: the lanes that enter its box (in the mask),
/// with chapter 3's intersect_node arithmetic lane for lane (its exits widened after the
/// minimum, as chapter 3's are for a ray with tnear < 0), and each lane's entry distance in
/// `entry` (+inf for the lanes that miss). `box_tfar` is the packet's, as it stands.
template <int P, int N>
RTK_INLINE uint32_t enter_child(const NodeN<N>& node, int c, const PacketBox<P>& p, vfloat<P> box_tfar,
                                vfloat<P>& entry) {
  const char* base = reinterpret_cast<const char*>(&node) + sizeof(float) * size_t(c);
  auto plane = [base](size_t row) { return vfloat<P>(*reinterpret_cast<const float*>(base + row)); };
  const vfloat<P> nx = (p.org_x - plane(p.near_x)) * p.neg_rdir_x;
  const vfloat<P> ny = (p.org_y - plane(p.near_y)) * p.neg_rdir_y;
  const vfloat<P> nz = (p.org_z - plane(p.near_z)) * p.neg_rdir_z;
  const vfloat<P> fx = (p.org_x - plane(p.far_x)) * p.neg_rdir_x;
  const vfloat<P> fy = (p.org_y - plane(p.far_y)) * p.neg_rdir_y;
  const vfloat<P> fz = (p.org_z - plane(p.far_z)) * p.neg_rdir_z;
  const vfloat<P> dist = max(max(nx, ny), max(nz, p.tnear));
  const vfloat<P> exit = min(widen_exit(min(min(fx, fy), fz)), box_tfar);
  const vbool<P> in = dist <= exit;
  entry = select(in, dist, vfloat<P>(std::numeric_limits<float>::infinity()));
  return movemask(in);
}
// [ch09-packet-node]

// [ch09-packet-leaf]
/// Tests the packet against the triangles of `count` blocks of M precomputed triangles, one
/// triangle at a time broadcast to all lanes: Möller-Trumbore with the rays in the lanes. A lane's
/// closest hit is kept by chapter 2's rule (smaller t, then lower primID), which does not
/// depend on the order the triangles come in, so a lane ends with its single-ray hit.
/// Occlusion: lanes hit are blocked and leave the packet. Returns whether any lane changed.
template <int P, int M, bool kOcclusion>
RTK_INLINE bool packet_leaf(RayPacket<P>& p, const TriangleM<M>* blocks, uint32_t count, Hit* hits, uint8_t* blocked) {
  bool changed = false;
  for (uint32_t b = 0; b < count; ++b) {
    const TriangleM<M>& t = blocks[b];
    for (int j = 0; j < M; ++j) {
      if (j > 0 && t.prim[j] == t.prim[0]) break;  // unused lanes repeat lane 0
      auto lane = [&](const float (&row)[3][M]) {
        return Vec3v<P>(vfloat<P>(row[0][j]), vfloat<P>(row[1][j]), vfloat<P>(row[2][j]));
      };
      TriangleHitsK<P> h{};
      const vbool<P> valid = MoellerTrumbore::intersect<P>(p.pre, p.tfar, lane(t.v0), lane(t.e1), lane(t.e2), lane(t.Ng), h);
      uint32_t mask = movemask(valid) & p.live;
      if (mask == 0) continue;
      if constexpr (kOcclusion) {
        for (const int i : set_bits(mask)) blocked[i] = 1;
        p.live &= ~mask;
        changed = true;
        if (p.live == 0) return true;
      } else {
        alignas(64) float ts[P], us[P], vs[P];
        h.t.store(ts), h.u.store(us), h.v.store(vs);
        const uint32_t prim = t.prim[j];
        for (const int i : set_bits(mask)) {
          if (!improves_on(ts[i], prim, hits[i])) continue;
          hits[i] = Hit{ts[i], us[i], vs[i], prim};
          changed = true;
        }
      }
    }
  }
  return changed;
}
// [ch09-packet-leaf]

/// After hits: each lane's interval ends at its closest hit, widened for the box tests.
template <int P>
RTK_INLINE void shorten_packet(RayPacket<P>& p, const Hit* hits) {
  alignas(64) float tf[P], btf[P];
  p.tfar.store(tf), p.box_tfar.store(btf);
  for (int i = 0; i < P; ++i)
    if (hits[i].found()) tf[i] = hits[i].t, btf[i] = conservative_tfar(hits[i].t, true);
  p.tfar = vfloat<P>::load(tf), p.box_tfar = vfloat<P>::load(btf);
}

// [ch09-packet-traverse]
/// Traces one packet through a BVHN whose leaves are blocks of M precomputed triangles. The
/// packet visits a node when any live lane enters it. The children entered are pushed farthest
/// first (as the first lane that enters each sees them), each with every lane's entry distance,
/// and an entry popped is skipped unless some lane enters it before its own closest hit: per
/// lane, chapter 3's cull at pop. A lane sees every leaf its single ray would see (and perhaps
/// more, which only costs time).
template <int P, int N, int M, bool kOcclusion>
void trace_packet(const BVHN<N>& bvh, const Ray* rays, RayPacket<P>& p, Hit* hits, uint8_t* blocked) {
  using Leaf = LeafIntersector<TriangleMLayout<M>, MoellerTrumbore, true>;
  StatsCounter<false> no_stats;
  // A copy the compiler may keep in registers: nothing the traversal calls can reach it.
  const PacketBox<P> box = p.box;
  // Lanes that enter a subtree few enough to go alone: each ray through it with chapter 3's
  // traversal, from its closest hit so far, and the subtree is not pushed for the packet.
  auto alone = [&](NodeRef child, uint32_t mask) {
    bool changed = false;
    for (const int i : set_bits(mask)) {
      Ray ray = rays[i];
      if constexpr (kOcclusion) {
        if (traverse_bvhn<N, Leaf, Tricks{}, true, false>(bvh, child, ray, hits[i], no_stats)) {
          blocked[i] = 1;
          p.live &= ~(1u << i);
          changed = true;
        }
      } else {
        if (hits[i].found()) ray.tfar = hits[i].t;
        changed |= traverse_bvhn<N, Leaf, Tricks{}, false, false>(bvh, child, ray, hits[i], no_stats);
      }
    }
    if (changed && !kOcclusion) shorten_packet(p, hits);
  };
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const std::byte* leaf_bytes = bvh.leaves.bytes.data();
  NodeRef refs[kBvhStackSize<N>];
  vfloat<P> entries[kOcclusion ? 1 : kBvhStackSize<N>];  // occlusion culls nothing
  int top = 0;
  refs[top] = bvh.root;
  if constexpr (!kOcclusion) entries[top] = vfloat<P>(-kInf);
  ++top;
  while (top > 0) {
    const NodeRef ref = refs[--top];
    uint32_t entering = p.live;
    if constexpr (!kOcclusion) {
      entering &= movemask(entries[top] <= p.box_tfar);
      if (entering == 0) continue;
    }
    if (!is_leaf(ref)) {
      const NodeN<N>& node = bvh.node(ref);
      // The children entered, sorted so that the nearest is pushed last.
      vfloat<P> entry[N];
      float key[N];
      int order[N];
      int k = 0;
      for (int c = 0; c < N; ++c) {
        // An unused slot (or an empty leaf) holds nothing: no box test.
        if (node.children[c] == kEmptyLeaf) continue;
        const uint32_t mask = enter_child<P, N>(node, c, box, p.box_tfar, entry[c]) & p.live;
        if (mask == 0) continue;
        if (std::popcount(mask) <= kAloneLanes) {
          alone(node.children[c], mask);
          if (kOcclusion && p.live == 0) return;
          continue;
        }
        alignas(64) float lanes[P];
        entry[c].store(lanes);
        key[c] = lanes[std::countr_zero(mask)];
        int at = k++;
        for (; at > 0 && key[order[at - 1]] < key[c]; --at) order[at] = order[at - 1];
        order[at] = c;
      }
      for (int i = 0; i < k; ++i) {
        refs[top] = node.children[order[i]];
        if constexpr (!kOcclusion) entries[top] = entry[order[i]];
        ++top;
      }
      continue;
    }
    const uint32_t count = leaf_blocks(ref);
    if (count == 0) continue;
    const auto* blocks = reinterpret_cast<const TriangleM<M>*>(leaf_bytes + leaf_offset(ref));
    // A leaf that at most M lanes enter: each tests the block's M triangles at once, as a single
    // ray does, which costs no more than the packet testing the M triangles one by one.
    if (!kOcclusion && std::popcount(entering) <= M) {
      bool changed = false;
      for (const int i : set_bits(entering)) {
        const typename Leaf::Precalc pre(rays[i]);
        float tfar = hits[i].found() ? hits[i].t : rays[i].tfar;
        changed |= Leaf::intersect(pre, rays[i], blocks, count, hits[i], tfar);
      }
      if (changed) shorten_packet(p, hits);
      continue;
    }
    if (packet_leaf<P, M, kOcclusion>(p, blocks, count, hits, blocked)) {
      if constexpr (kOcclusion) {
        if (p.live == 0) return;
      } else {
        shorten_packet(p, hits);
      }
    }
  }
}
// [ch09-packet-traverse]

}  // namespace rtk::RTK_ISA
