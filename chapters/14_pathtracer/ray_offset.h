/// \file
/// Spawning secondary rays without hitting the surface they leave: the hit point computed in
/// floating point lies a little above or below the true surface, and a ray that starts there
/// may find its own triangle again at t ~ 0 ("shadow acne").
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "01_base/vec3.h"

namespace rtk {

// [ch14-offset]
/// Moves a surface point off the surface along the geometric normal `n` (pointing to the side
/// the new ray leaves on), after Wächter and Binder, "A Fast and Robust Method for Avoiding
/// Self-Intersection" (Ray Tracing Gems, chapter 6, 2019). The offset is a fixed number of
/// units in the last place of each coordinate, added to the float's bits as an integer, so it
/// scales with the coordinate's magnitude, which is what the rounding error of the hit point
/// does: a fixed epsilon is too small far from the origin and too large near it. Near the
/// origin, where ulps become tiny, a small absolute offset takes over. The ray then starts
/// with tnear = 0 and needs no epsilon of its own.
inline Vec3f offset_ray_origin(Vec3f p, Vec3f n) {
  constexpr float kOrigin = 1.0f / 32.0f;        // below this magnitude: absolute offset
  constexpr float kFloatScale = 1.0f / 65536.0f;  // the absolute offset per unit normal
  constexpr float kIntScale = 256.0f;             // ulps per unit normal
  Vec3f out;
  for (int axis = 0; axis < 3; ++axis) {
    const float c = p[axis];
    const int32_t ulps = static_cast<int32_t>(kIntScale * n[axis]);
    // Adding to the bits moves away from zero for positive floats and toward it for
    // negative ones, hence the sign flip.
    const int32_t bits = std::bit_cast<int32_t>(c) + (c < 0.0f ? -ulps : ulps);
    out[axis] = std::fabs(c) < kOrigin ? c + kFloatScale * n[axis] : std::bit_cast<float>(bits);
  }
  return out;
}
// [ch14-offset]

}  // namespace rtk
