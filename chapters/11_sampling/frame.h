/// \file
/// Orthonormal frames: BSDFs and warping functions work in a local frame whose z axis is the
/// surface normal; a Frame converts directions to and from it.
#pragma once

#include <cmath>

#include "01_base/vec3.h"

namespace rtk {

// [ch11-frame]
/// An orthonormal basis (s, t, n) built from a unit normal without branches on the normal's
/// direction, except for the sign of n.z: Duff, Burgess, Christensen, Hery, Kensler, Liani and
/// Villemin, "Building an Orthonormal Basis, Revisited" (JCGT 6(1), 2017). It is continuous
/// everywhere but across n.z = 0 and accurate to a few ulps even near n = (0, 0, -1), where
/// Frisvad's original construction breaks down.
struct Frame {
  Vec3f s{1, 0, 0}, t{0, 1, 0}, n{0, 0, 1};

  /// The identity frame (the local frame itself).
  constexpr Frame() = default;

  /// The frame around unit normal `normal` (it must be normalised).
  explicit Frame(Vec3f normal) : n(normal) {
    const float sign = std::copysign(1.0f, normal.z);
    const float a = -1.0f / (sign + normal.z);
    const float b = normal.x * normal.y * a;
    s = {1.0f + sign * normal.x * normal.x * a, sign * b, -sign * normal.x};
    t = {b, sign + normal.y * normal.y * a, -normal.y};
  }

  /// A frame from three given orthonormal axes (used when a tangent is prescribed).
  constexpr Frame(Vec3f s_, Vec3f t_, Vec3f n_) : s(s_), t(t_), n(n_) {}

  /// World direction to local coordinates (projections onto the axes).
  constexpr Vec3f to_local(Vec3f w) const { return {dot(w, s), dot(w, t), dot(w, n)}; }
  /// Local direction to world coordinates.
  constexpr Vec3f to_world(Vec3f w) const { return s * w.x + t * w.y + n * w.z; }
};
// [ch11-frame]

}  // namespace rtk
