/// \file
/// The slab test: one ray against N axis-aligned boxes at once, the heart of BVH traversal.
///
/// A box is the intersection of three slabs, the space between two parallel planes. The ray
/// enters the box at the latest of its three slab entries and leaves it at the earliest of its
/// three exits; it hits the box when it enters before it leaves, within [tnear, tfar]. This is
/// the test of Kay and Kajiya ("Ray tracing complex scenes", SIGGRAPH 1986), in the form of
/// Williams et al. ("An efficient and robust ray-box intersection algorithm", JGT 2005) that
/// picks the near plane by the sign of the direction, with the NaN handling of Ize ("Robust BVH
/// ray traversal", JCGT 2013) left to the min/max rule of the SIMD wrappers.
#pragma once

#ifndef RTK_ISA
#error "slab.h belongs to kernel sources compiled once per ISA (see cmake/rtk_isa.cmake)"
#endif

#include <cmath>
#include <limits>

#include "01_base/boxes_soa.h"
#include "01_base/ray.h"
#include "01_base/simd.h"

namespace rtk::RTK_ISA {

/// A ray prepared for slab tests against N boxes: its origin and reciprocal direction broadcast
/// to all lanes, and for each axis the side of a box (0 lower, 1 upper) that it meets first.
template <int N>
struct SlabRay {
  vfloat<N> org[3];   ///< the origin, per axis
  vfloat<N> rdir[3];  ///< 1 / direction, per axis: +-inf where the direction is +-0
  vfloat<N> tnear;    ///< the start of the ray's interval
  vfloat<N> tfar;     ///< the end of the ray's interval
  int near_side[3];   ///< per axis, the side (0 lower, 1 upper) whose plane the ray meets first
};

// [ch01-slab-setup]
/// Prepares a ray for slab tests. The reciprocal is an exact division, so that every variant
/// gets the same bits; a zero direction component gives an infinite reciprocal with the zero's
/// sign. A ray that is not a ray (rtk::is_valid) gets the empty interval [+inf, -inf] and hits
/// nothing.
template <int N>
SlabRay<N> make_slab_ray(const Ray& ray) {
  SlabRay<N> r;
  const bool valid = is_valid(ray);
  for (int axis = 0; axis < 3; ++axis) {
    const float d = valid ? ray.dir[axis] : 1.0f;
    r.org[axis] = vfloat<N>(valid ? ray.org[axis] : 0.0f);
    r.rdir[axis] = vfloat<N>(1.0f / d);
    r.near_side[axis] = std::signbit(d) ? 1 : 0;
  }
  const float inf = std::numeric_limits<float>::infinity();
  r.tnear = vfloat<N>(valid ? ray.tnear : inf);
  r.tfar = vfloat<N>(valid ? ray.tfar : -inf);
  return r;
}
// [ch01-slab-setup]

// [ch01-slab]
/// Tests the ray against boxes [first, first + N) of `boxes` (first a multiple of N). Returns
/// the lanes whose box the ray hits, and sets `entry` to where it enters each box's interval.
template <int N>
RTK_INLINE vbool<N> intersect_slabs(const SlabRay<N>& r, const BoxesSoA& boxes, size_t first,
                                    vfloat<N>& entry) {
  vfloat<N> t_near[3], t_far[3];
  for (int axis = 0; axis < 3; ++axis) {
    const float* near_planes = boxes.planes(r.near_side[axis], axis) + first;
    const float* far_planes = boxes.planes(1 - r.near_side[axis], axis) + first;
    t_near[axis] = (vfloat<N>::load(near_planes) - r.org[axis]) * r.rdir[axis];
    t_far[axis] = (vfloat<N>::load(far_planes) - r.org[axis]) * r.rdir[axis];
  }
  // A ray parallel to a slab and starting in one of its planes computes 0 * inf = NaN there.
  // min and max return their second argument when the first is NaN, so the NaN goes first:
  // the slab is then ignored, and a ray lying on a face of the closed box hits it.
  const vfloat<N> t_enter = max(t_near[0], max(t_near[1], max(t_near[2], r.tnear)));
  const vfloat<N> t_exit = min(t_far[0], min(t_far[1], min(t_far[2], r.tfar)));
  entry = t_enter;
  return t_enter <= t_exit;
}
// [ch01-slab]

}  // namespace rtk::RTK_ISA
