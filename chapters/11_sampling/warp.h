/// \file
/// Warping functions: maps from the unit square to disks, hemispheres, spheres, cones and
/// triangles, each with the density of the points it produces. Directions are in a local
/// frame with z up (see frame.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "01_base/platform.h"
#include "01_base/vec3.h"
#include "11_sampling/vec2.h"

namespace rtk {

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kInvPi = std::numbers::inv_pi_v<float>;

/// sqrt of max(x, 0): rounding can push 1 - x*x a hair below zero.
inline float safe_sqrt(float x) { return std::sqrt(std::max(x, 0.0f)); }

// [ch11-disk]
/// Cosine and sine of an angle within [-pi/4, pi/4], by their Taylor series: on so short an
/// interval the terms up to x^10 and x^9 leave an error below a tenth of a float's ulp, and a
/// few multiplications cost less than the library's sincosf, which must first reduce any
/// angle to this interval. The series are summed by Estrin's scheme, pairs of terms joined
/// by x^4 and x^8 computed beside them: six operations deep for the cosine where Horner's
/// rule, each step waiting for the one before, is eleven, and a bounce's next ray waits for
/// this direction.
inline Vec2f cos_sin_quarter(float x) {
  const float x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
  const float c = ((1.0f - x2 * (1.0f / 2)) + x4 * (1.0f / 24 - x2 * (1.0f / 720))) +
                  x8 * (1.0f / 40320 - x2 * (1.0f / 3628800));
  const float s = x * (((1.0f - x2 * (1.0f / 6)) + x4 * (1.0f / 120 - x2 * (1.0f / 5040))) +
                       x8 * (1.0f / 362880));
  return {c, s};
}

/// A uniform point on the unit disk by Shirley and Chiu's concentric map ("A Low Distortion
/// Map Between Disk and Square", JGT 1997): squares around the centre become rings, so
/// stratification survives the warp (a polar map would squeeze the strata near the centre).
/// The angle is measured from the nearer axis, so that it stays within 45 degrees of it.
inline Vec2f sample_uniform_disk(Vec2f u) {
  const float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
  if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f};
  // The angle from the x axis when |a| > |b|, else from the y axis. Which one it is depends on
  // the random point, so it is chosen by selects rather than by a branch that would be
  // mispredicted half the time; the arithmetic is the same either way.
  const bool from_y = !(std::fabs(a) > std::fabs(b));
  const float r = select_bits(from_y, a, b), other = select_bits(from_y, b, a);
  const Vec2f cs = cos_sin_quarter((kPi / 4.0f) * (other / r));
  const float along = r * cs.x, across = r * cs.y;
  return {select_bits(from_y, along, across), select_bits(from_y, across, along)};
}
/// The density of sample_uniform_disk on the disk: 1 / pi.
inline constexpr float pdf_uniform_disk() { return kInvPi; }
// [ch11-disk]

// [ch11-cosine]
/// A direction on the upper hemisphere with density cos(theta) / pi, by Malley's method: a
/// uniform point of the disk lifted onto the hemisphere. The cosine in the density cancels
/// the cosine of the rendering equation, which is why diffuse surfaces sample this way.
/// The height comes from the disk point's radius, the larger of |2u - 1|'s coordinates,
/// rather than from the point: 1 - x^2 - y^2 loses its digits near the rim, where a height
/// that should be 0 comes out as the square root of a rounding error, up to 5e-4, while
/// (1 - r)(1 + r) keeps it within 3e-8; and the radius is known before the angle, so the
/// square root need not wait for the division and the series.
inline Vec3f sample_cosine_hemisphere(Vec2f u) {
  const Vec2f d = sample_uniform_disk(u);
  const float r = std::max(std::fabs(2.0f * u.x - 1.0f), std::fabs(2.0f * u.y - 1.0f));
  return {d.x, d.y, safe_sqrt((1.0f - r) * (1.0f + r))};
}
/// The density of sample_cosine_hemisphere: cos(theta) / pi above the surface, 0 below.
inline float pdf_cosine_hemisphere(float cos_theta) {
  return cos_theta > 0.0f ? cos_theta * kInvPi : 0.0f;
}
// [ch11-cosine]

/// A uniform direction on the upper hemisphere (z >= 0): z = u.x, phi = 2 pi u.y. The sine is
/// sqrt((1 - z)(1 + z)), whose factors are exact or nearly, not sqrt(1 - z^2), which rounds
/// z^2 first and loses the digits of a small sine near the pole.
inline Vec3f sample_uniform_hemisphere(Vec2f u) {
  const float z = u.x, r = safe_sqrt((1.0f - z) * (1.0f + z)), phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
/// The density of sample_uniform_hemisphere: 1 / (2 pi).
inline constexpr float pdf_uniform_hemisphere() { return 0.5f * kInvPi; }

/// A uniform direction on the unit sphere: z uniform in [-1, 1] (Archimedes: equal heights
/// cut equal areas), phi uniform. The sine comes from u rather than from the rounded z:
/// 1 - z^2 = 4u(1 - u), so that a u too small to move z off 1 still moves the direction off
/// the pole.
inline Vec3f sample_uniform_sphere(Vec2f u) {
  const float z = 1.0f - 2.0f * u.x, r = 2.0f * safe_sqrt(u.x * (1.0f - u.x)),
              phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
/// The density of sample_uniform_sphere: 1 / (4 pi).
inline constexpr float pdf_uniform_sphere() { return 0.25f * kInvPi; }

// [ch11-cone]
/// 1 - cos(theta), as 2 sin^2(theta / 2): computed as 1 - std::cos(theta) it is lost below
/// theta = 2.4e-4 (the cosine rounds to 1), and holds few correct digits above that for small
/// angles, where floats just below 1 are 6e-8 apart.
inline float one_minus_cos(float theta) {
  const float s = std::sin(0.5f * theta);
  return 2.0f * s * s;
}

/// 1 - cos of the angle between unit vectors a and b, as |a - b|^2 / 2: the difference of two
/// nearly equal vectors is exact, component by component, where their dot product would round
/// to 1. Lights use it to tell whether a direction lies inside a narrow cone.
inline float one_minus_cos_between(Vec3f a, Vec3f b) {
  const Vec3f d = a - b;
  return 0.5f * dot(d, d);
}

/// A uniform direction in the cone of directions within angle theta_max of +z, the cone given
/// by h = 1 - cos(theta_max) (one_minus_cos): the sphere's construction with z restricted to
/// [1 - h, 1]. It draws 1 - z = u h rather than z, and the sine from it as sqrt((1 - z)(1 + z)),
/// so that a cone as narrow as the sun's (h = 1.1e-5) or a star's keeps every digit of its
/// angles: z itself may round to 1, the direction's sideways part does not.
inline Vec3f sample_uniform_cone(Vec2f u, float one_minus_cos_max) {
  const float w = u.x * one_minus_cos_max;  // 1 - z
  const float r = safe_sqrt(w * (2.0f - w)), phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), 1.0f - w};
}
/// The density of sample_uniform_cone: one over the cone's solid angle 2 pi (1 - cos theta_max).
inline float pdf_uniform_cone(float one_minus_cos_max) { return 1.0f / (2.0f * kPi * one_minus_cos_max); }
// [ch11-cone]

// [ch11-triangle]
/// Uniform barycentric coordinates (b0, b1, b2) of a triangle: b0 = 1 - sqrt(u.x) picks the
/// distance from the first vertex with density growing linearly (the triangle widens), and
/// u.y splits the remainder. The density is 1 / area on any triangle, 2 on the (b1, b2)
/// half-square.
inline Vec3f sample_uniform_triangle(Vec2f u) {
  const float su = std::sqrt(u.x);
  const float b1 = su * (1.0f - u.y), b2 = su * u.y;
  return {1.0f - b1 - b2, b1, b2};
}
// [ch11-triangle]

/// Spherical coordinates of a direction: theta from +z in [0, pi], phi in [0, 2 pi). The polar
/// angle is atan2 of the sideways length and the height, not acos of the height: near a pole
/// the height rounds to a float within 6e-8 of 1 in magnitude, and acos of it would put every
/// direction within 2.4e-4 radians of the pole on the pole itself.
inline float spherical_theta(Vec3f w) { return std::atan2(std::sqrt(w.x * w.x + w.y * w.y), w.z); }
/// The azimuth of a direction in [0, 2 pi), measured from +x toward +y.
inline float spherical_phi(Vec3f w) {
  const float p = std::atan2(w.y, w.x);
  return p < 0.0f ? p + 2.0f * kPi : p;
}

}  // namespace rtk
