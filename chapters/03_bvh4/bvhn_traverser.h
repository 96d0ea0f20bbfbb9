/// \file
/// Single-ray traversal of a BVH4/BVH8 with the guide's tricks (section 4.1.1), each one
/// switched by a compile-time Tricks value, and an optional statistics mode. Generic over the
/// leaf intersector, like chapter 2's BVH2 traversal.
#pragma once

#ifndef RTK_ISA
#error "bvhn_traverser.h belongs to kernel sources compiled once per ISA"
#endif

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <utility>

#include "01_base/platform.h"
#include "01_base/simd.h"
#include "02_bvh2/conservative_exit.h"
#include "03_bvh4/bvh4.h"
#include "03_bvh4/push_order.h"

namespace rtk::RTK_ISA {

/// The ray as the N-wide box test sees it: every value broadcast to all lanes.
template <int N>
struct BvhNRay {
  vfloat<N> org_x, org_y, org_z;
  /// -1/dir: the box test computes (org - plane) * (-1/dir), which equals (plane - org) / dir
  /// and lets the compiler read the plane straight from memory into the subtraction.
  vfloat<N> neg_rdir_x, neg_rdir_y, neg_rdir_z;
  /// -1/dir for the far planes: neg_rdir, or for exits widened `folded` (conservative_exit.h)
  /// neg_rdir widened, which makes every exit conservative at no cost per node.
  vfloat<N> far_rdir_x, far_rdir_y, far_rdir_z;
  /// The ray's interval, clamped to finite values: unused child slots have all bounds at +inf,
  /// and only a finite interval keeps such a box out whatever the direction. tfar is widened
  /// like a slab exit (conservative_tfar).
  vfloat<N> tnear, tfar;
  /// Byte offsets in a node of the near and far rows of each axis, chosen by direction sign.
  size_t near_x, near_y, near_z, far_x, far_y, far_z;
  /// For `fused` exits only: chapter 2's fused_offset for the near planes (with 1/dir) and the
  /// far ones (with the widened 1/dir, -far_rdir), so that a slab distance is
  /// plane * (-neg_rdir) - offset, one fused operation.
  vfloat<N> near_offset_x, near_offset_y, near_offset_z, far_offset_x, far_offset_y, far_offset_z;
};

/// Whether this ISA's variant fuses multiply-adds (AVX2 and AVX-512), and so has the `fused` test.
#if defined(__FMA__)
inline constexpr bool kFusedBoxTest = true;
#else
inline constexpr bool kFusedBoxTest = false;
#endif

// [ch03-ray-lanes]
/// A ray's origin and direction as 4-wide vectors, x, y, z in lanes 0 to 2. A Ray is org,
/// tnear, dir, time, tfar, so each is one unaligned load; lane 3 (tnear or time) is carried
/// along and never read.
struct RayAxes {
  vfloat<4> org, dir;
  explicit RayAxes(const Ray& ray) : org(vfloat<4>::loadu(&ray.org.x)), dir(vfloat<4>::loadu(&ray.dir.x)) {}
};
static_assert(offsetof(Ray, tnear) == 3 * sizeof(float) && offsetof(Ray, time) == 7 * sizeof(float));
// [ch03-ray-lanes]

/// Whether a ray with tnear >= 0 may take the `fused` test: its offsets must be finite, which
/// every origin within 2^60 of zero and direction no shorter than 2^-60 on any axis makes sure
/// of (a reciprocal of at most 2^60, a product of at most 2^120), without computing them. An
/// axis-parallel ray, a zero component, or a NaN fails the test and is tested `folded`.
RTK_INLINE bool fused_applies(const Ray& ray) {
  const RayAxes a(ray);
  const vbool<4> within = (abs(a.org) <= vfloat<4>(0x1p60f)) & (abs(a.dir) >= vfloat<4>(0x1p-60f));
  return (movemask(within) & 7u) == 7u;
}

/// Prepares a valid ray for the N-wide box test, once per ray, its exits widened as `widening`
/// says (`folded` and `fused` only for a ray with tnear >= 0, as traverse_bvhn chooses). The
/// three axes are computed side by side in one 4-wide register, then each value is broadcast
/// to the N lanes of the box test: a ray that visits a dozen nodes spends a good part of its
/// instructions here, and lane for lane the operations round as they would one float at a time.
template <int N>
RTK_INLINE BvhNRay<N> make_bvhn_ray(const Ray& ray, ExitWidening widening = ExitWidening::after_min) {
  constexpr float kMax = std::numeric_limits<float>::max();
  const RayAxes a(ray);
  BvhNRay<N> r;
  auto spread = [](vfloat<4> v, vfloat<N>& x, vfloat<N>& y, vfloat<N>& z) {
    x = vfloat<N>(v[0]), y = vfloat<N>(v[1]), z = vfloat<N>(v[2]);
  };
  spread(a.org, r.org_x, r.org_y, r.org_z);
  // 1/(+-0) = +-inf keeps the sign of a zero component, so the planes chosen below and the
  // distances computed with them agree.
  const vfloat<4> rdir = vfloat<4>(1.0f) / a.dir, neg_rdir = -rdir;
  spread(neg_rdir, r.neg_rdir_x, r.neg_rdir_y, r.neg_rdir_z);
  const bool folded = widening == ExitWidening::folded || widening == ExitWidening::fused;
  const vfloat<4> neg_far_rdir = folded ? folded_reciprocal(neg_rdir) : neg_rdir;
  spread(neg_far_rdir, r.far_rdir_x, r.far_rdir_y, r.far_rdir_z);
  if (widening == ExitWidening::fused) {
    // [ch03-fused-ray]
    // The far planes' offsets are made with the folded reciprocal above, turned positive.
    spread(fused_offset(a.org, rdir, true), r.near_offset_x, r.near_offset_y, r.near_offset_z);
    spread(fused_offset(a.org, -neg_far_rdir, false), r.far_offset_x, r.far_offset_y, r.far_offset_z);
    // [ch03-fused-ray]
  }
  // + 0 turns -0 into +0, which compare equal as floats; the `fused` test compares the bits
  // as integers, where they do not.
  r.tnear = vfloat<N>((ray.tnear > -kMax ? ray.tnear : -kMax) + 0.0f);
  r.tfar = vfloat<N>(conservative_tfar(ray.tfar, widening != ExitWidening::none) + 0.0f);
  // [ch03-near-far-offsets]
  // Rows are N floats; the two rows of an axis are adjacent, lower first, and the sign bits of
  // 1/dir say which of the two an axis enters by.
  constexpr size_t kRow = sizeof(float) * N;
  const uint32_t negative = sign_bits(rdir);
  r.near_x = (negative & 1u) * kRow, r.near_y = (2 + ((negative >> 1) & 1u)) * kRow,
  r.near_z = (4 + ((negative >> 2) & 1u)) * kRow;
  r.far_x = r.near_x ^ kRow, r.far_y = r.near_y ^ kRow, r.far_z = r.near_z ^ kRow;
  // [ch03-near-far-offsets]
  return r;
}

/// Lowers the far end of the ray's interval after a hit.
template <int N>
RTK_INLINE void shorten(BvhNRay<N>& r, float tfar, bool conservative = true) {
  r.tfar = vfloat<N>(conservative_tfar(tfar, conservative) + 0.0f);  // -0 as +0 (make_bvhn_ray)
}

/// Tests the ray against the N children of a node, its exits widened as W says (the ray was
/// made for W). Returns the hit mask (bit i for child i) and leaves each child's entry distance
/// in `dist`.
template <int N, Tricks T, ExitWidening W>
RTK_INLINE uint32_t intersect_node(const NodeN<N>& node, const BvhNRay<N>& r, vfloat<N>& dist) {
  vfloat<N> nx, ny, nz, fx, fy, fz;
  if constexpr (T.near_far_by_sign) {
    // [ch03-box-sign]
    const char* base = reinterpret_cast<const char*>(&node);
    auto row = [base](size_t offset) { return vfloat<N>::load(reinterpret_cast<const float*>(base + offset)); };
    if constexpr (W == ExitWidening::fused) {
      // [ch03-box-fused]
      // -(plane * -rdir) - offset, rounded once: plane * rdir - offset.
      nx = fnmsub(row(r.near_x), r.neg_rdir_x, r.near_offset_x);
      ny = fnmsub(row(r.near_y), r.neg_rdir_y, r.near_offset_y);
      nz = fnmsub(row(r.near_z), r.neg_rdir_z, r.near_offset_z);
      fx = fnmsub(row(r.far_x), r.far_rdir_x, r.far_offset_x);
      fy = fnmsub(row(r.far_y), r.far_rdir_y, r.far_offset_y);
      fz = fnmsub(row(r.far_z), r.far_rdir_z, r.far_offset_z);
      // [ch03-box-fused]
    } else {
      nx = (r.org_x - row(r.near_x)) * r.neg_rdir_x;
      ny = (r.org_y - row(r.near_y)) * r.neg_rdir_y;
      nz = (r.org_z - row(r.near_z)) * r.neg_rdir_z;
      fx = (r.org_x - row(r.far_x)) * r.far_rdir_x;
      fy = (r.org_y - row(r.far_y)) * r.far_rdir_y;
      fz = (r.org_z - row(r.far_z)) * r.far_rdir_z;
    }
    // [ch03-box-sign]
  } else {
    static_assert(W != ExitWidening::folded, "folding needs to know the far planes");
    // [ch03-box-minmax]
    const vfloat<N> lx = (r.org_x - vfloat<N>::load(node.lower_x)) * r.neg_rdir_x;
    const vfloat<N> ux = (r.org_x - vfloat<N>::load(node.upper_x)) * r.neg_rdir_x;
    const vfloat<N> ly = (r.org_y - vfloat<N>::load(node.lower_y)) * r.neg_rdir_y;
    const vfloat<N> uy = (r.org_y - vfloat<N>::load(node.upper_y)) * r.neg_rdir_y;
    const vfloat<N> lz = (r.org_z - vfloat<N>::load(node.lower_z)) * r.neg_rdir_z;
    const vfloat<N> uz = (r.org_z - vfloat<N>::load(node.upper_z)) * r.neg_rdir_z;
    nx = min(lx, ux), fx = max(lx, ux);
    ny = min(ly, uy), fy = max(ly, uy);
    nz = min(lz, uz), fz = max(lz, uz);
    // [ch03-box-minmax]
  }
  if constexpr (W == ExitWidening::fused) {
    // [ch03-box-integer]
    // The fused distances are never NaN (a finite reciprocal and offset; an empty slot's
    // infinite planes give infinities) nor -0 (the offset is never 0), and the interval
    // starts at tnear >= +0. Compared as signed integers, two floats keep their order where
    // one is >= +0, and every negative float (-0 included) is below every one that is not.
    // So the largest entry, which is >= tnear, is the same as integers, and it lies beyond an
    // exit as integers exactly when it does as floats, whichever exit is the least of several
    // negative ones. Integer minimum, maximum and comparison take one cycle where their float
    // forms take up to four, on the chain from a node's bytes to the next node.
    const vint<N> entry = max(max(as_int(nx), as_int(ny)), max(as_int(nz), as_int(r.tnear)));
    const vint<N> exit = min(min(as_int(fx), as_int(fy)), min(as_int(fz), as_int(r.tfar)));
    dist = as_float(entry);
    return movemask(entry > exit) ^ ((1u << N) - 1);
    // [ch03-box-integer]
  }
  // [ch03-box-combine]
  // The ray's own limits come last: where a slab gives 0 * inf = NaN (a ray lying in the
  // plane of a face), min and max return their second operand and the NaN drops out.
  // The slabs' exit is widened by its rounding bound (already, when it is folded into the ray)
  // before the ray's own (already widened) limit joins it, so that rounding never separates an
  // entry from an equal exit.
  dist = max(max(nx, ny), max(nz, r.tnear));
  vfloat<N> exit;
  if constexpr (W == ExitWidening::after_min) exit = min(widen_exit(min(min(fx, fy), fz)), r.tfar);
  else exit = min(min(fx, fy), min(fz, r.tfar));  // folded into far_rdir, or none
  return movemask(dist <= exit);
  // [ch03-box-combine]
}

// [ch03-prefetch]
/// Starts loading the node or leaf that `ref` names: all the lines of an inner node (a Node8 is
/// four), the first line of a leaf's blocks. Any BVH whose node(ref) gives its node type.
template <class Bvh>
RTK_INLINE void prefetch_child(const Bvh& bvh, const std::byte* leaf_bytes, NodeRef ref) {
  if (!is_leaf(ref)) {
    const auto& node = bvh.node(ref);
    const char* bytes = reinterpret_cast<const char*>(&node);
    for (size_t line = 0; line < sizeof(node); line += 64) prefetch_l1(bytes + line);
  } else {
    prefetch_l1(leaf_bytes + leaf_offset(ref));  // the empty leaf too: a hint never faults
  }
}
// [ch03-prefetch]

#if defined(__AVX512F__)
// [ch03-sort-network]
// The one place a kernel leaves the SIMD wrappers: sorting eight keys in a register takes
// 64-bit minimum, maximum and cross-lane permutes, which only AVX-512 has as single
// instructions. The other ISAs keep sort_pushed, and the tests hold the two to the same order.
static_assert(sizeof(BvhStackEntry) == 16 && offsetof(BvhStackEntry, dist) == 8);

/// One layer of a bitonic sorting network on eight 64-bit keys, all in one register: each lane
/// meets the lane `J` places away (its index xor J) and keeps the larger or the smaller of the
/// two, as the lane's place in a block of K says, so that after the six layers of K = 2, 4, 8
/// the keys fall from lane 0 to lane 7.
template <int K, int J>
RTK_INLINE __m512i bitonic_layer(__m512i key) {
  constexpr auto keeps_larger = [] {
    unsigned m = 0;
    for (int i = 0; i < 8; ++i)
      if (((i & J) == 0) != ((i & K) != 0)) m |= 1u << i;
    return static_cast<__mmask8>(m);
  }();
  const __m512i partner = _mm512_set_epi64(7 ^ J, 6 ^ J, 5 ^ J, 4 ^ J, 3 ^ J, 2 ^ J, 1 ^ J, 0 ^ J);
  const __m512i other = _mm512_permutexvar_epi64(partner, key);
  return _mm512_mask_max_epi64(_mm512_min_epi64(key, other), keeps_larger, key, other);
}

/// The children of `mask` (four or more) sorted in registers and pushed farthest first, as
/// sort_pushed orders them, and the nearest returned: each child's key is push_key's (distance
/// bits in the order of signed integers over the slot), made for all eight lanes at once; the
/// lanes of children missed sort below every hit.
RTK_INLINE NodeRef push_sorted_by_network(const NodeRef* children, uint32_t mask, const vfloat<8>& dist,
                                          BvhStackEntry*& sp) {
  // + 0 turns -0 into +0, which compare equal as floats but not as integers.
  const __m256i bits = _mm256_castps_si256(_mm256_add_ps(dist.m, _mm256_setzero_ps()));
  const __m256i ordered = _mm256_xor_si256(bits, _mm256_srli_epi32(_mm256_srai_epi32(bits, 31), 1));
  __m512i key = _mm512_or_si512(_mm512_slli_epi64(_mm512_cvtepi32_epi64(ordered), 32),
                                _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0));
  const __m512i unsorted = key;
  key = _mm512_mask_mov_epi64(_mm512_set1_epi64(std::numeric_limits<int64_t>::min()),
                              static_cast<__mmask8>(mask), key);
  key = bitonic_layer<2, 1>(key);
  key = bitonic_layer<4, 2>(key);
  key = bitonic_layer<4, 1>(key);
  key = bitonic_layer<8, 4>(key);
  key = bitonic_layer<8, 2>(key);
  key = bitonic_layer<8, 1>(key);
  const __m512i slot = _mm512_and_si512(key, _mm512_set1_epi64(7));
  const __m512i refs = _mm512_permutexvar_epi64(slot, _mm512_loadu_si512(children));
  const __m512i dists = _mm512_permutexvar_epi64(slot, _mm512_cvtepu32_epi64(_mm256_castps_si256(dist.m)));
  // Entries {ref, dist} side by side: eight of them in two stores, of which the first k - 1
  // are the pushed ones (the stack has room for the rest).
  _mm512_storeu_si512(sp, _mm512_permutex2var_epi64(refs, _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0), dists));
  _mm512_storeu_si512(sp + 4, _mm512_permutex2var_epi64(refs, _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4), dists));
  sp += pop_count(mask) - 1;
  // The nearest child, found apart from the sort so that the next node's load need not wait
  // for the network: the smallest key of the children hit.
  const __m512i hit_keys = _mm512_mask_mov_epi64(_mm512_set1_epi64(std::numeric_limits<int64_t>::max()),
                                                 static_cast<__mmask8>(mask), unsorted);
  return children[_mm512_reduce_min_epi64(hit_keys) & 7];
}
// [ch03-sort-network]
#endif

// [ch03-next-child]
/// After a node's box test: the hit child (`mask`, not 0) the ray visits next, the other hit
/// children pushed on the stack at `sp` in the order the tricks ask for, each with its entry
/// distance from `dist`. Chapter 8's motion traversal makes the same choice.
template <int N, Tricks T, bool kOcclusion>
RTK_INLINE NodeRef next_child(const NodeRef* children, uint32_t mask, const vfloat<N>& dist,
                              BvhStackEntry*& sp) {
  // [ch03-stored-order]
  // A shadow ray: the first hit child in stored order next, the others pushed so that they
  // pop in stored order too (the highest slot deepest). No distances: nothing is culled.
  if constexpr (kOcclusion && T.shadow_rays_in_stored_order) {
    const int first = pop_lowest_bit(mask);
    while (mask != 0) *sp++ = {children[pop_highest_bit(mask)], 0.0f};
    return children[first];
  }
  // [ch03-stored-order]
  alignas(64) float d[N];
  dist.store(d);
  const int i0 = pop_lowest_bit(mask);
  // 1 child hit: keep going without the stack.
  if constexpr (T.one_hit_path) {
    if (mask == 0) return children[i0];
  }
  // 2 children hit: push the farther, go to the nearer.
  if constexpr (T.two_hit_path) {
    if (mask != 0 && (mask & (mask - 1)) == 0) {
      const int i1 = bit_scan_forward(mask);
      const bool swap = d[i1] < d[i0];
      const int near = swap ? i1 : i0, far = swap ? i0 : i1;
      *sp++ = {children[far], d[far]};
      return children[near];
    }
  }
  // 3 children hit: ordered without branches (push_three).
  if constexpr (T.sorted_push) {
    if (pop_count(mask) == 2) {
      const int i1 = pop_lowest_bit(mask);
      return push_three(children, d, i0, i1, bit_scan_forward(mask), sp);
    }
  }
#if defined(__AVX512F__)
  // 4 or more children of a BVH8 node, on AVX-512: sorted in registers (push_sorted_by_network).
  if constexpr (N == 8 && T.sorted_push) {
    if (pop_count(mask) >= 3) return push_sorted_by_network(children, mask | (1u << i0), dist, sp);
  }
#endif
  // More children hit (or a fast path switched off): push them all, walking the mask with bit
  // scans, sort them nearest-on-top, and continue with the top.
  BvhStackEntry* const first = sp;
  *sp++ = {children[i0], d[i0]};
  while (mask != 0) {
    const int i = pop_lowest_bit(mask);
    *sp++ = {children[i], d[i]};
  }
  if constexpr (T.sorted_push) sort_pushed(first, sp);
  --sp;
  return sp->ref;
}
// [ch03-next-child]

/// The counters a statistics-mode traversal keeps; an empty shell in the fast path.
template <bool kStats>
struct StatsCounter {
  RTK_INLINE void node(uint32_t) {}
  RTK_INLINE void leaf(uint32_t) {}
  RTK_INLINE void cull() {}
};
template <>
struct StatsCounter<true> {
  TraversalStats s;
  RTK_INLINE void node(uint32_t mask) { ++s.nodes, ++s.children_hit[size_t(pop_count(mask))]; }
  RTK_INLINE void leaf(uint32_t blocks) { ++s.leaves, s.primitives += blocks; }
  RTK_INLINE void cull() { ++s.culled; }
};

/// Traces one valid ray through the subtree of `from` with its box tests' exits widened as W
/// says (traverse_bvhn below chooses W).
template <int N, class Leaf, Tricks T, bool kOcclusion, bool kStats, ExitWidening W>
bool traverse_bvhn_widened(const BVHN<N>& bvh, NodeRef from, const Ray& ray, Hit& hit, StatsCounter<kStats>& stats) {
  const typename Leaf::Precalc pre(ray);
  constexpr bool kWiden = W != ExitWidening::none;
  BvhNRay<N> r = make_bvhn_ray<N>(ray, W);
  float tfar = ray.tfar;
  // Cull at pop needs shrinking hits; an occlusion ray stops at its first hit. Pushed entries
  // beyond the widened far end are culled (conservative_exit.h).
  constexpr bool kCull = T.cull_at_pop && !kOcclusion;
  float cull = conservative_tfar(tfar, kWiden);

  BvhStackEntry stack[kBvhStackSize<N>];
  BvhStackEntry* sp = stack;
  *sp++ = {kTerminal, -std::numeric_limits<float>::infinity()};  // never culled: ends the loop
  const std::byte* leaf_bytes = bvh.leaves.bytes.data();
  bool found = false;

  NodeRef cur = from;
  for (;;) {
    // [ch03-descend]
    while (!is_leaf(cur)) {
      const NodeN<N>& node = bvh.node(cur);
      // Early pop: the next stack entry is read before the box test, off its critical path.
      BvhStackEntry next;
      if constexpr (T.early_pop) next = sp[-1];
      vfloat<N> dist;
      uint32_t mask = intersect_node<N, T, W>(node, r, dist);
      stats.node(mask);

      // 0 children hit.
      if (mask == 0) {
        if constexpr (T.early_pop) {
          --sp;
          if (kCull && next.dist > cull) {
            stats.cull();
            goto pop;
          }
          cur = next.ref;
          continue;
        } else {
          goto pop;
        }
      }
      if constexpr (T.prefetch_children) {
        for (int i : set_bits(mask)) prefetch_child(bvh, leaf_bytes, node.children[i]);
      }
      // 1, 2 or more children hit.
      cur = next_child<N, T, kOcclusion>(node.children, mask, dist, sp);
    }
    // [ch03-descend]
    if (cur == kTerminal) break;
    // Leaf: the intersector tests its blocks and, for a closest hit, shortens the ray.
    {
      const uint32_t count = leaf_blocks(cur);
      stats.leaf(count);
      const auto* blocks = reinterpret_cast<const typename Leaf::Block*>(leaf_bytes + leaf_offset(cur));
      if constexpr (kOcclusion) {
        if (Leaf::occluded(pre, ray, blocks, count, tfar)) return true;
      } else if (Leaf::intersect(pre, ray, blocks, count, hit, tfar)) {
        found = true;
        shorten(r, tfar, kWiden);
        cull = conservative_tfar(tfar, kWiden);
      }
    }
  pop:
    // [ch03-pop]
    --sp;
    if constexpr (kCull) {
      while (sp->dist > cull) {
        stats.cull();
        --sp;
      }
    }
    cur = sp->ref;
    // [ch03-pop]
  }
  return found;
}

// [ch03-exit-widening]
/// Traces one valid ray through the subtree of `from` (bvh.root for the whole BVH) of an N-wide
/// BVH. For a closest hit (kOcclusion false) it returns whether it found a hit that beats `hit`
/// (chapter 2's rule) and writes it there; for occlusion, whether anything blocks. The exits are
/// widened once per ray, folded into it, wherever chapter 2 allows (a ray with tnear >= 0, and
/// the far planes known by the direction's signs); otherwise at every node. Where the ISA fuses
/// multiply-adds, a closest-hit ray that fused_applies to makes each slab distance in one
/// fused operation (`fused`).
template <int N, class Leaf, Tricks T, bool kOcclusion, bool kStats>
RTK_INLINE bool traverse_bvhn(const BVHN<N>& bvh, NodeRef from, const Ray& ray, Hit& hit,
                              StatsCounter<kStats>& stats) {
  using enum ExitWidening;
  if constexpr (!T.conservative_exits)
    return traverse_bvhn_widened<N, Leaf, T, kOcclusion, kStats, none>(bvh, from, ray, hit, stats);
  else if constexpr (!T.near_far_by_sign)
    return traverse_bvhn_widened<N, Leaf, T, kOcclusion, kStats, after_min>(bvh, from, ray, hit, stats);
  else if (!(ray.tnear >= 0.0f))
    return traverse_bvhn_widened<N, Leaf, T, kOcclusion, kStats, after_min>(bvh, from, ray, hit, stats);
  else if constexpr (kFusedBoxTest)
    return fused_applies(ray)
               ? traverse_bvhn_widened<N, Leaf, T, kOcclusion, kStats, fused>(bvh, from, ray, hit, stats)
               : traverse_bvhn_widened<N, Leaf, T, kOcclusion, kStats, folded>(bvh, from, ray, hit, stats);
  else
    return traverse_bvhn_widened<N, Leaf, T, kOcclusion, kStats, folded>(bvh, from, ray, hit, stats);
}
// [ch03-exit-widening]

/// Traces rays[i] into hits[i] with one trick configuration; statistics go to `stats` when
/// kStats is set. Invalid rays miss without traversal.
template <int N, class Leaf, Tricks T, bool kStats>
void intersect_rays(const BVHN<N>& bvh, std::span<const Ray> rays, std::span<Hit> hits, TraversalStats* stats) {
  StatsCounter<kStats> counter;
  for (size_t i = 0; i < rays.size(); ++i) {
    Hit hit;
    if (is_valid(rays[i])) {
      if constexpr (kStats) ++counter.s.rays;
      traverse_bvhn<N, Leaf, T, false, kStats>(bvh, bvh.root, rays[i], hit, counter);
    }
    hits[i] = hit;
  }
  if constexpr (kStats) *stats += counter.s;
  else (void)stats;
}

/// Occlusion of rays[i] into occluded[i] with one trick configuration.
template <int N, class Leaf, Tricks T, bool kStats>
void occluded_rays(const BVHN<N>& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded, TraversalStats* stats) {
  StatsCounter<kStats> counter;
  Hit unused;
  for (size_t i = 0; i < rays.size(); ++i) {
    bool blocked = false;
    if (is_valid(rays[i])) {
      if constexpr (kStats) ++counter.s.rays;
      blocked = traverse_bvhn<N, Leaf, T, true, kStats>(bvh, bvh.root, rays[i], unused, counter);
    }
    occluded[i] = blocked ? 1 : 0;
  }
  if constexpr (kStats) *stats += counter.s;
  else (void)stats;
}

// [ch03-batch-kernels]
/// The batch kernels of an N-wide BVH whose leaves Leaf reads, all tricks on unless T says
/// otherwise, in the form every structure hands out (02_bvh2/trace_kernels.h): `structure` is
/// the BVHN<N>. Chapters 6 to 10 make their kernels with this too.
template <int N, class Leaf, Tricks T = Tricks{}>
void intersect_batch(const void* structure, std::span<const Ray> rays, std::span<Hit> hits) {
  require_same_size(rays.size(), hits.size());
  intersect_rays<N, Leaf, T, false>(*static_cast<const BVHN<N>*>(structure), rays, hits, nullptr);
}
template <int N, class Leaf, Tricks T = Tricks{}>
void occluded_batch(const void* structure, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  require_same_size(rays.size(), occluded.size());
  occluded_rays<N, Leaf, T, false>(*static_cast<const BVHN<N>*>(structure), rays, occluded, nullptr);
}
template <int N, class Leaf, Tricks T = Tricks{}>
constexpr TraceKernels bvhn_batch_kernels() {
  return {&intersect_batch<N, Leaf, T>, &occluded_batch<N, Leaf, T>};
}
// [ch03-batch-kernels]

/// The kernels of one width and leaf intersector for every configuration of kTrickConfigs, with
/// and without statistics, chosen at run time from a table.
template <int N, class Leaf>
struct BvhNKernels {
  using IntersectFn = void (*)(const BVHN<N>&, std::span<const Ray>, std::span<Hit>, TraversalStats*);
  using OccludedFn = void (*)(const BVHN<N>&, std::span<const Ray>, std::span<uint8_t>, TraversalStats*);

  template <size_t... I>
  static constexpr auto intersect_table(std::index_sequence<I...>) {
    return std::array<IntersectFn, 2 * sizeof...(I)>{
        &intersect_rays<N, Leaf, kTrickConfigs[I].tricks, false>...,
        &intersect_rays<N, Leaf, kTrickConfigs[I].tricks, true>...};
  }
  template <size_t... I>
  static constexpr auto occluded_table(std::index_sequence<I...>) {
    return std::array<OccludedFn, 2 * sizeof...(I)>{
        &occluded_rays<N, Leaf, kTrickConfigs[I].tricks, false>...,
        &occluded_rays<N, Leaf, kTrickConfigs[I].tricks, true>...};
  }

  /// The table index of a configuration, or an exception naming the compiled ones.
  static size_t index(const Tricks& tricks, bool with_stats, size_t rays, size_t results) {
    require_same_size(rays, results);
    const size_t i = trick_config_index(tricks);
    if (i == kTrickConfigCount)
      throw std::invalid_argument("this trick configuration is not compiled; the compiled ones are: " +
                                  trick_config_names());
    return i + (with_stats ? kTrickConfigCount : 0);
  }

  static void intersect(const BVHN<N>& bvh, const Tricks& tricks, std::span<const Ray> rays,
                        std::span<Hit> hits, TraversalStats* stats) {
    static constexpr auto table = intersect_table(std::make_index_sequence<kTrickConfigCount>{});
    table[index(tricks, stats != nullptr, rays.size(), hits.size())](bvh, rays, hits, stats);
  }
  static void occluded(const BVHN<N>& bvh, const Tricks& tricks, std::span<const Ray> rays,
                       std::span<uint8_t> occluded, TraversalStats* stats) {
    static constexpr auto table = occluded_table(std::make_index_sequence<kTrickConfigCount>{});
    table[index(tricks, stats != nullptr, rays.size(), occluded.size())](bvh, rays, occluded, stats);
  }
};

}  // namespace rtk::RTK_ISA
