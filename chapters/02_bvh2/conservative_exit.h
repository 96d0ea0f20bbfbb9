/// \file
/// The slab test made conservative: where the exact test would find a box hit, the rounded one
/// does too, so that no traversal of the book ever culls a triangle its ray/triangle test would
/// hit, however far from the origin the scene lies. Per-ISA template: include from kernel
/// sources only.
#pragma once

#ifndef RTK_ISA
#error "conservative_exit.h belongs to kernel sources compiled once per ISA"
#endif

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

/// `exit` moved away from zero by kExitWidening: larger ahead of the origin, more negative
/// behind it; infinities stay infinite and NaN stays NaN.
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

}  // namespace rtk::RTK_ISA
