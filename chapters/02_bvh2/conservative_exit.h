/// \file
/// The slab test made conservative: where the exact test would find a box hit, the rounded one
/// does too, so that no traversal of the book ever culls a triangle its ray/triangle test would
/// hit, however far from the origin the scene lies. Per-ISA template: include from kernel
/// sources only.
#pragma once

#ifndef RTK_ISA
#error "conservative_exit.h belongs to kernel sources compiled once per ISA"
#endif

#include <algorithm>
#include <cmath>
#include <limits>

#include "01_base/simd.h"

namespace rtk::RTK_ISA {

// [ch02-conservative-exit]
/// How far a slab distance may be from the exact one, relatively. A distance is
/// (plane - org) * (1 / dir): three roundings, the subtraction, the reciprocal and the product,
/// so it is within a factor 1 +- g of the exact value, g = 3u / (1 - 3u) with u = 2^-24
/// (Higham's gamma_3). An entry and an exit that are equal in exact arithmetic, where a ray
/// passes through a box's edge or corner (a ray aimed at a mesh vertex does), can then come out
/// in the wrong order, and the box is missed. Ize ("Robust BVH ray traversal", JCGT 2013)
/// widens the exit by twice that bound; the widening's own product rounds once more, so RTK
/// widens by four units in the last place of 1, a little more than 2 g.
inline constexpr float kExitWidening = 4 * 0x1p-23f;

/// `exit` raised by kExitWidening of its magnitude: larger ahead of the origin, nearer to it
/// behind; infinities stay infinite and NaN stays NaN.
template <int N>
RTK_INLINE vfloat<N> widen_exit(vfloat<N> exit) {
  return max(exit * vfloat<N>(1.0f + kExitWidening), exit * vfloat<N>(1.0f - kExitWidening));
}

/// The far end of a ray's interval as the box tests and the cull at pop compare with it:
/// widened like a slab exit, so that a box whose entry equals the closest hit's distance (where
/// a triangle at the same distance may still wait) is still visited, and kept finite, so that
/// a node's unused slots, whose planes are all +inf, stay out whatever the direction.
/// (With `widen` false, only kept finite: for measuring what the widening buys.)
RTK_INLINE float conservative_tfar(float tfar, bool widen = true) {
  constexpr float kMax = std::numeric_limits<float>::max();
  const float factor = !widen ? 1.0f : tfar >= 0.0f ? 1.0f + kExitWidening : 1.0f - kExitWidening;
  const float widened = tfar * factor;
  return widened < kMax ? widened : kMax;
}
// [ch02-conservative-exit]

// [ch02-folded-widening]
/// Where a box test widens its exits. `after_min` is widen_exit() on the nearest of the slab
/// exits, three operations at every node on the path a ray waits along. `folded` does the same
/// once per ray: the far planes' distances are computed with -1/dir already widened
/// (folded_reciprocal), so they come out widened, and a node's test is left with the
/// subtractions, products, minima and maxima of the exact one. It is valid only for a ray whose
/// interval starts at or after its origin (tnear >= 0): such a ray keeps a box only where an
/// exit is at least tnear, so only exits of 0 and above matter, and for them a larger factor is
/// a larger exit. Behind the origin the same factor would lower an exit, so a ray with
/// tnear < 0 is widened after the minimum. `none` is the exact slab test, for measurements.
/// `fused` is `folded` with each slab distance made by one fused multiply-add (fused_offset),
/// where the ISA has them.
enum class ExitWidening { none, after_min, folded, fused };

/// -1/dir for the far planes of a ray whose exits are widened `folded`: the same bound as
/// widen_exit, applied before the product instead of after it. The product that makes a slab
/// exit now rounds four times (the subtraction, the reciprocal, this product, the last one)
/// instead of three, each by at most u = 2^-24, and the entry it is compared with three times:
/// with the factor 1 + 8u, (1 - u)^4 (1 + 8u) >= (1 + u)^3, so an exit equal to an entry in
/// exact arithmetic is never rounded below it, as with widen_exit.
template <int N>
RTK_INLINE vfloat<N> folded_reciprocal(vfloat<N> neg_rdir) { return neg_rdir * vfloat<N>(1.0f + kExitWidening); }
// [ch02-folded-widening]

// [ch02-fused-offset]
/// A `fused` slab distance is plane * rdir - offset in one fused multiply-add, which rounds
/// once: rdir is 1/dir for the near planes and the widened reciprocal (-folded_reciprocal) for
/// the far ones, and the offset stands for org * rdir, which rounds too. So the rounded product
/// is moved away by 4u of itself (at least by the smallest normal float, below which a product
/// rounds by a fixed amount), up for the near planes and down for the far ones: whatever both
/// roundings did, the near offset is at least the exact org * rdir and the far one at most.
/// Rounding keeps order, so an entry comes out at most, and an exit at least, the exact
/// difference of plane and origin times rdir rounded once. That is one rounding fewer than the
/// `folded` test's subtraction and product, and kExitWidening, which covers those, covers this.
/// Only for offsets that are finite: an axis-parallel ray's reciprocal is infinite, and its
/// product with the plane minus an infinite offset would be infinity minus infinity. Never
/// zero: where the move lands on 0 (q is minus the margin, or the margin), the offset goes one
/// smallest normal float further the same way, so that no slab distance is -0, which equals +0
/// as a float but not in chapter 3's comparisons of the bits as integers. Computed lane for
/// lane: chapter 3 makes a ray's three axes in one 4-wide register.
template <int N>
RTK_INLINE vfloat<N> fused_offset(vfloat<N> org, vfloat<N> rdir, bool near) {
  const vfloat<N> kMin(std::numeric_limits<float>::min());
  const vfloat<N> q = org * rdir;
  const vfloat<N> margin = max(abs(q) * vfloat<N>(4 * 0x1p-24f), kMin);
  const vfloat<N> offset = near ? q + margin : q - margin;
  return select(offset != vfloat<N>(0.0f), offset, near ? kMin : -kMin);
}
// [ch02-fused-offset]

}  // namespace rtk::RTK_ISA
