/// \file
/// Fresnel equations and the directions of specular reflection and refraction. Directions
/// are in the local shading frame (z is the normal) and point away from the surface.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "01_base/vec3.h"
#include "01_base/color.h"

namespace rtk {

/// The mirror direction of w about the local normal (0, 0, 1).
constexpr Vec3f reflect_local(Vec3f w) { return {-w.x, -w.y, w.z}; }

/// The mirror direction of w about the unit vector m (a microfacet normal).
constexpr Vec3f reflect(Vec3f w, Vec3f m) { return 2.0f * dot(w, m) * m - w; }

// [ch12-fresnel-dielectric]
/// The unpolarised Fresnel reflectance of a smooth dielectric interface, exact: the mean of
/// the squared amplitude ratios for light polarised parallel and perpendicular to the plane of
/// incidence. `cos_i` is the cosine of the incident direction with the normal; `eta` the ratio
/// n_inside / n_outside, where the normal points outside. A negative cos_i means the light
/// arrives from inside, and the ratio is inverted. Total internal reflection returns 1.
inline float fresnel_dielectric(float cos_i, float eta) {
  cos_i = std::clamp(cos_i, -1.0f, 1.0f);
  if (cos_i < 0.0f) {
    eta = 1.0f / eta;
    cos_i = -cos_i;
  }
  // Snell's law gives the transmitted angle; past the critical angle there is none.
  const float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return 1.0f;
  const float cos_t = std::sqrt(1.0f - sin2_t);
  const float r_parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const float r_perpendicular = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}
// [ch12-fresnel-dielectric]

// [ch12-fresnel-conductor]
/// The unpolarised Fresnel reflectance of a conductor with complex index of refraction
/// eta + i k (per colour channel), seen from a medium of index 1, exact. This is the usual
/// closed form in terms of a^2 + b^2 = |n^2 - sin^2|, e.g. Pharr, Jakob and Humphreys,
/// "Physically Based Rendering", 3rd ed., section 8.2.1.
inline float fresnel_conductor(float cos_i, float eta, float k) {
  cos_i = std::clamp(std::fabs(cos_i), 0.0f, 1.0f);
  const float cos2 = cos_i * cos_i, sin2 = 1.0f - cos2;
  const float eta2 = eta * eta, k2 = k * k;
  const float t0 = eta2 - k2 - sin2;
  const float a2_plus_b2 = std::sqrt(t0 * t0 + 4.0f * eta2 * k2);
  const float t1 = a2_plus_b2 + cos2;
  const float a = std::sqrt(std::max(0.5f * (a2_plus_b2 + t0), 0.0f));
  const float t2 = 2.0f * cos_i * a;
  const float rs = (t1 - t2) / (t1 + t2);
  const float t3 = cos2 * a2_plus_b2 + sin2 * sin2;
  const float t4 = t2 * sin2;
  const float rp = rs * (t3 - t4) / (t3 + t4);
  return 0.5f * (rp + rs);
}
/// The conductor reflectance per colour channel.
inline Color fresnel_conductor(float cos_i, Color eta, Color k) {
  return {fresnel_conductor(cos_i, eta.r, k.r), fresnel_conductor(cos_i, eta.g, k.g),
          fresnel_conductor(cos_i, eta.b, k.b)};
}
// [ch12-fresnel-conductor]

/// The refracted direction of w (pointing away from the surface, on the side of n, so
/// dot(w, n) > 0) into a medium with relative index eta = n_transmitted / n_incident, or
/// nothing under total internal reflection. The result points away from the surface on the
/// other side.
inline std::optional<Vec3f> refract(Vec3f w, Vec3f n, float eta) {
  const float cos_i = dot(w, n);
  const float sin2_t = std::max(0.0f, 1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return std::nullopt;
  const float cos_t = std::sqrt(1.0f - sin2_t);
  return -w / eta + (cos_i / eta - cos_t) * n;
}

}  // namespace rtk
