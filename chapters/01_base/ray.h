/// \file
/// The ray and the hit: what the kernels take and give back.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "01_base/vec3.h"

namespace rtk {

/// A ray segment: the points org + t * dir for tnear <= t <= tfar. `dir` need not be normalized;
/// t is measured in units of dir. `time` in [0, 1] is the shutter time (motion blur).
/// The field order is the record of a `.rays` file, so a file maps onto an array of Rays.
struct Ray {
  Vec3f org;
  float tnear = 0.0f;
  Vec3f dir;
  float time = 0.0f;
  float tfar = std::numeric_limits<float>::infinity();
};
static_assert(sizeof(Ray) == 36, "a Ray is one 36-byte record of a .rays file");

/// The primitive ID that means "no hit".
inline constexpr uint32_t kInvalidPrim = 0xFFFFFFFFu;

/// The closest hit along a ray: the distance, the barycentric weights u and v of the triangle's
/// second and third vertex (hit = (1-u-v) p0 + u p1 + v p2) and the triangle's index.
/// The layout is the record of a `.hits` file.
struct Hit {
  float t = 0.0f;
  float u = 0.0f;
  float v = 0.0f;
  uint32_t prim = kInvalidPrim;

  constexpr bool found() const { return prim != kInvalidPrim; }
};
static_assert(sizeof(Hit) == 16, "a Hit is one 16-byte record of a .hits file");

/// Whether a ray is a ray at all. NaN anywhere, an infinite origin or direction component, a
/// zero direction, or tnear > tfar make it a miss that is never traversed (tfar = +inf is fine).
inline bool is_valid(const Ray& r) {
  const bool finite = is_finite(r.org) && is_finite(r.dir) && !std::isnan(r.tnear) && !std::isnan(r.tfar);
  const bool nonzero = r.dir.x != 0.0f || r.dir.y != 0.0f || r.dir.z != 0.0f;
  return finite && nonzero && r.tnear <= r.tfar;
}

}  // namespace rtk
