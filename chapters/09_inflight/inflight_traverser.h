/// \file
/// Several rays of a batch in flight on one thread: each ray keeps its own stack and state, and
/// the loop visits one node (or leaf) of one ray, then moves on to the next ray, so that the
/// memory of one ray's next node is on its way while the others compute. Built from chapter 3's
/// box test, descent choice and prefetch, and any leaf intersector of chapters 6 and 7: per ray,
/// the visits are exactly those of chapter 3's traversal, so the answers are too.
#pragma once

#ifndef RTK_ISA
#error "inflight_traverser.h belongs to kernel sources compiled once per ISA"
#endif

#include <cstddef>
#include <limits>
#include <new>
#include <type_traits>
#include <span>

#include "01_base/platform.h"
#include "01_base/simd.h"
#include "03_bvh4/bvhn_traverser.h"
#include "09_inflight/inflight.h"

namespace rtk::RTK_ISA {

// [ch09-state]
/// What one ray in flight carries between its visits: chapter 3's prepared ray, its stack, the
/// node it visits next, and its closest hit so far. The leaf test's per-ray values are built in
/// place when the ray starts (they have no default).
template <int N, class Leaf>
struct alignas(64) InflightRay {
  using Precalc = typename Leaf::Precalc;
  BvhNRay<N> r;
  NodeRef cur;          ///< the node or leaf this ray visits next (already asked of the cache)
  BvhStackEntry* sp;    ///< one past the top of `stack`
  float tfar;           ///< the closest hit so far (the ray's tfar before any)
  float cull;           ///< tfar widened: pushed entries beyond it are skipped
  size_t index;         ///< the ray's place in the batch
  bool blocked;         ///< occlusion: a leaf blocks the ray
  Hit hit;              ///< the closest hit so far
  alignas(Precalc) unsigned char pre_bytes[sizeof(Precalc)];
  BvhStackEntry stack[kBvhStackSize<N>];

  const Precalc& pre() const { return *std::launder(reinterpret_cast<const Precalc*>(pre_bytes)); }
};
// [ch09-state]

/// Makes `s` trace rays[index] from the root, as chapter 3's traverse_bvhn starts a ray.
template <int N, class Leaf, bool kPrefetch>
RTK_INLINE void start_ray(InflightRay<N, Leaf>& s, const BVHN<N>& bvh, const std::byte* leaf_bytes,
                          const Ray& ray, size_t index) {
  static_assert(std::is_trivially_destructible_v<typename Leaf::Precalc>);
  new (s.pre_bytes) typename Leaf::Precalc(ray);
  s.r = make_bvhn_ray<N>(ray, ExitWidening::after_min);
  s.tfar = ray.tfar;
  s.cull = conservative_tfar(s.tfar, true);
  s.index = index;
  s.blocked = false;
  s.hit = Hit{};
  s.stack[0] = {kTerminal, -std::numeric_limits<float>::infinity()};  // never culled: ends the ray
  s.sp = s.stack + 1;
  s.cur = bvh.root;
  if constexpr (kPrefetch) prefetch_child(bvh, leaf_bytes, s.cur);
}

// [ch09-visit]
/// One step of one ray: visits the node or leaf `s.cur` with chapter 3's tricks (all on), then
/// chooses the ray's next node and asks the cache for it, without waiting for it. Returns true
/// when the ray is done: its stack is empty, or (occlusion) a leaf blocks it.
template <int N, class Leaf, bool kOcclusion, bool kPrefetch>
RTK_INLINE bool visit(InflightRay<N, Leaf>& s, const BVHN<N>& bvh, const std::byte* leaf_bytes, const Ray& ray) {
  // The prefetch switch governs chapter 3's prefetch of the hit children too, so that "off"
  // means no software prefetch at all.
  constexpr Tricks T{.prefetch_children = kPrefetch};
  constexpr bool kCull = !kOcclusion;
  BvhStackEntry* sp = s.sp;
  if (!is_leaf(s.cur)) {
    const NodeN<N>& node = bvh.node(s.cur);
    const BvhStackEntry next = sp[-1];  // early pop
    vfloat<N> dist;
    const uint32_t mask = intersect_node<N, T, ExitWidening::after_min>(node, s.r, dist);
    if (mask != 0) {
      // The children the ray enters are all asked for; the one it visits next is among them.
      if constexpr (kPrefetch)
        for (int i : set_bits(mask)) prefetch_child(bvh, leaf_bytes, node.children[i]);
      s.cur = next_child<N, T, kOcclusion>(node.children, mask, dist, sp);
      s.sp = sp;
      return false;
    }
    --sp;
    if (!(kCull && next.dist > s.cull)) {
      s.sp = sp;
      s.cur = next.ref;
      if (s.cur == kTerminal) return true;
      if constexpr (kPrefetch) prefetch_child(bvh, leaf_bytes, s.cur);
      return false;
    }
  } else {
    const uint32_t count = leaf_blocks(s.cur);
    const auto* blocks = reinterpret_cast<const typename Leaf::Block*>(leaf_bytes + leaf_offset(s.cur));
    if constexpr (kOcclusion) {
      if (Leaf::occluded(s.pre(), ray, blocks, count, s.tfar)) {
        s.blocked = true;
        return true;
      }
    } else if (Leaf::intersect(s.pre(), ray, blocks, count, s.hit, s.tfar)) {
      shorten(s.r, s.tfar, true);
      s.cull = conservative_tfar(s.tfar, true);
    }
  }
  // Pop, skipping entries that begin beyond the closest hit (chapter 3's cull at pop).
  --sp;
  if constexpr (kCull)
    while (sp->dist > s.cull) --sp;
  s.sp = sp;
  s.cur = sp->ref;
  if (s.cur == kTerminal) return true;
  // A popped node was asked for when it was pushed, maybe long ago: ask again now, a few
  // visits of the other rays before this one reads it.
  if constexpr (kPrefetch) prefetch_child(bvh, leaf_bytes, s.cur);
  return false;
}
// [ch09-visit]

// [ch09-loop]
/// Traces a batch with K rays in flight: each ray takes one step in turn, round robin; a ray
/// that is done hands its slot to the next valid ray of the batch. Invalid rays miss without a
/// slot. `done(s)` writes a finished ray's answer.
template <int N, class Leaf, bool kOcclusion, int K, bool kPrefetch, class Done, class Miss>
void trace_inflight(const BVHN<N>& bvh, std::span<const Ray> rays, Done&& done, Miss&& miss) {
  InflightRay<N, Leaf> slots[K];
  int active[K];  // the slots whose rays are still in flight, in turn order
  int live = 0;
  const std::byte* leaf_bytes = bvh.leaves.bytes.data();
  size_t next = 0;
  // Gives slot k the next valid ray of the batch; false when none is left.
  auto refill = [&](int k) {
    while (next < rays.size()) {
      const size_t i = next++;
      if (!is_valid(rays[i])) {
        miss(i);
        continue;
      }
      start_ray<N, Leaf, kPrefetch>(slots[k], bvh, leaf_bytes, rays[i], i);
      return true;
    }
    return false;
  };
  for (int k = 0; k < K; ++k)
    if (refill(k)) active[live++] = k;
  while (live > 0) {
    for (int a = 0; a < live;) {
      InflightRay<N, Leaf>& s = slots[active[a]];
      if (!visit<N, Leaf, kOcclusion, kPrefetch>(s, bvh, leaf_bytes, rays[s.index])) {
        ++a;
        continue;
      }
      done(s);
      if (!refill(active[a])) active[a] = active[--live];  // the batch is drained: close ranks
      else ++a;
    }
  }
}
// [ch09-loop]

/// The batch kernels with K rays in flight, in the form of 02_bvh2/trace_kernels.h: rays[i]
/// gives hits[i] (or occluded[i]), as chapter 3's kernels give them.
template <int N, class Leaf, int K, bool kPrefetch>
void inflight_intersect_batch(const void* structure, std::span<const Ray> rays, std::span<Hit> hits) {
  require_same_size(rays.size(), hits.size());
  trace_inflight<N, Leaf, false, K, kPrefetch>(
      *static_cast<const BVHN<N>*>(structure), rays,
      [&](const InflightRay<N, Leaf>& s) { hits[s.index] = s.hit; }, [&](size_t i) { hits[i] = Hit{}; });
}
template <int N, class Leaf, int K, bool kPrefetch>
void inflight_occluded_batch(const void* structure, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  require_same_size(rays.size(), occluded.size());
  trace_inflight<N, Leaf, true, K, kPrefetch>(
      *static_cast<const BVHN<N>*>(structure), rays,
      [&](const InflightRay<N, Leaf>& s) { occluded[s.index] = s.blocked ? 1 : 0; },
      [&](size_t i) { occluded[i] = 0; });
}
template <int N, class Leaf, int K, bool kPrefetch>
constexpr TraceKernels inflight_batch_kernels() {
  return {&inflight_intersect_batch<N, Leaf, K, kPrefetch>, &inflight_occluded_batch<N, Leaf, K, kPrefetch>};
}

}  // namespace rtk::RTK_ISA
