/// \file
/// K points or directions in structure-of-arrays form: what a ray/triangle test reads for K
/// triangles at once (chapter 2 onwards). Per-ISA template (include from kernel sources only).
#pragma once

#ifndef RTK_ISA
#error "vec3v.h belongs to kernel sources compiled once per ISA (see cmake/rtk_isa.cmake)"
#endif

#include <limits>

#include "01_base/simd.h"
#include "01_base/vec3.h"

namespace rtk::RTK_ISA {

/// The largest finite float: intersectors report no hit at an infinite distance.
inline constexpr float kMaxFloat = std::numeric_limits<float>::max();

/// Three vectors of K lanes: lane i holds the x, y and z of the i-th point.
template <int K>
struct Vec3v {
  vfloat<K> x, y, z;

  Vec3v() = default;
  Vec3v(vfloat<K> x_, vfloat<K> y_, vfloat<K> z_) : x(x_), y(y_), z(z_) {}
  /// The same point in every lane (a ray's origin or direction).
  explicit Vec3v(Vec3f p) : x(p.x), y(p.y), z(p.z) {}
  /// Loads lanes [first, first + K) of three SoA arrays (aligned to 4 K bytes).
  static Vec3v load(const float* xs, const float* ys, const float* zs, size_t first) {
    return {vfloat<K>::load(xs + first), vfloat<K>::load(ys + first), vfloat<K>::load(zs + first)};
  }
  /// The component along `axis` (0, 1, 2); the axis is chosen per ray, not per lane.
  const vfloat<K>& operator[](int axis) const { return axis == 0 ? x : axis == 1 ? y : z; }
};

// Each operation is written out in one fixed order, so that every ISA and width rounds the
// same way and the variants can be compared bit for bit.
template <int K> RTK_INLINE Vec3v<K> operator+(const Vec3v<K>& a, const Vec3v<K>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <int K> RTK_INLINE Vec3v<K> operator-(const Vec3v<K>& a, const Vec3v<K>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <int K> RTK_INLINE vfloat<K> dot(const Vec3v<K>& a, const Vec3v<K>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// The cross product. Swapping the arguments, or negating one, negates the result exactly:
/// each component is a difference of two products, and rounding is symmetric.
template <int K> RTK_INLINE Vec3v<K> cross(const Vec3v<K>& a, const Vec3v<K>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

}  // namespace rtk::RTK_ISA
