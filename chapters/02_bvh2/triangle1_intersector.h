/// \file
/// The leaf intersector of chapters 2 and 3: Möller-Trumbore on one Triangle1 at a time.
///
/// Traversal code is a template over a *leaf intersector*: a class with
/// - `Block` and `kLayout`: the block type it reads and the name of its layout (LeafBlocks);
/// - `Precalc`: what it computes once per ray (constructed from the Ray);
/// - `intersect(pre, ray, blocks, count, hit, tfar)`: finds the closest hit among `count` blocks
///   with t in [ray.tnear, tfar], writes it to `hit`, lowers `tfar` to its t and returns true,
///   or returns false and touches nothing;
/// - `occluded(pre, ray, blocks, count, tfar)`: whether any hit lies in [ray.tnear, tfar].
/// Chapters 6 and 7 plug other layouts and intersectors into the same traversal this way.
#pragma once

#ifndef RTK_ISA
#error "triangle1_intersector.h belongs to kernel sources compiled once per ISA"
#endif

#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>

#include "01_base/platform.h"
#include "01_base/ray.h"
#include "02_bvh2/triangle1.h"

namespace rtk::RTK_ISA {

/// Möller-Trumbore ("Fast, minimum storage ray-triangle intersection", JGT 1997) on a
/// precomputed Triangle1, two-sided, in plain float arithmetic: the same instructions in every
/// variant, so that every variant finds the same hits bit for bit.
struct Triangle1Intersector {
  using Block = Triangle1;
  static constexpr std::string_view kLayout = Triangle1Layout::kName;

  /// Nothing to precompute for one triangle at a time.
  struct Precalc {
    explicit Precalc(const Ray&) {}
  };

  /// `x` with its sign flipped where `s` is negative (on the bits, so -0 flips too).
  static RTK_INLINE float xorsign(float x, float s) {
    uint32_t a, b;
    std::memcpy(&a, &x, 4);
    std::memcpy(&b, &s, 4);
    a ^= b & 0x80000000u;
    std::memcpy(&x, &a, 4);
    return x;
  }

  // [ch02-moeller-trumbore]
  /// Tests one triangle; on a hit in [ray.tnear, tfar] sets t, u, v and returns true.
  static RTK_INLINE bool test(const Triangle1& tri, const Ray& ray, float tfar, float& t,
                              float& u, float& v) {
    // The determinant is the volume spanned by the direction and the edges: zero when the ray
    // is parallel to the plane of the triangle, or when the triangle has no area.
    const Vec3f pvec = cross(ray.dir, tri.e2);
    const float det = dot(tri.e1, pvec);
    if (det == 0.0f) return false;
    // Work with |det| and the signs folded into the numerators, so that the division waits
    // until the ray is known to cross the triangle: most tests end before it.
    const float abs_det = std::fabs(det);
    const Vec3f tvec = ray.org - tri.v0;
    const float un = xorsign(dot(tvec, pvec), det);
    if (!(un >= 0.0f && un <= abs_det)) return false;
    const Vec3f qvec = cross(tvec, tri.e1);
    const float vn = xorsign(dot(ray.dir, qvec), det);
    if (!(vn >= 0.0f && un + vn <= abs_det)) return false;
    const float inv_det = 1.0f / abs_det;
    t = xorsign(dot(tri.e2, qvec), det) * inv_det;
    // A tiny determinant can overflow 1/|det|: a hit at infinity is no hit.
    if (!(t >= ray.tnear && t <= tfar && t <= std::numeric_limits<float>::max())) return false;
    u = un * inv_det;
    v = vn * inv_det;
    return true;
  }
  // [ch02-moeller-trumbore]

  /// The closest hit among `count` triangles (later ones win ties: t <= tfar).
  static RTK_INLINE bool intersect(const Precalc&, const Ray& ray, const Triangle1* tris,
                                   uint32_t count, Hit& hit, float& tfar) {
    bool found = false;
    for (uint32_t i = 0; i < count; ++i) {
      float t, u, v;
      if (test(tris[i], ray, tfar, t, u, v)) {
        hit = Hit{t, u, v, tris[i].prim};
        tfar = t;
        found = true;
      }
    }
    return found;
  }

  /// Whether any of `count` triangles is hit in [ray.tnear, tfar].
  static RTK_INLINE bool occluded(const Precalc&, const Ray& ray, const Triangle1* tris,
                                  uint32_t count, float tfar) {
    for (uint32_t i = 0; i < count; ++i) {
      float t, u, v;
      if (test(tris[i], ray, tfar, t, u, v)) return true;
    }
    return false;
  }
};

}  // namespace rtk::RTK_ISA
