/// \file
/// The Möller-Trumbore ray/triangle test for one ray against K triangles: RTK's one
/// implementation of it, which every leaf layout and every structure uses.
///
/// Möller and Trumbore, "Fast, minimum storage ray/triangle intersection", Journal of
/// Graphics Tools 2(1), 1997. The fastest of the book's three tests, and the one that leaks
/// between long thin triangles: chapter 7 shows why, and adds the two that do not.
/// Per-ISA template: include from kernel sources only.
#pragma once

#include "01_base/ray.h"
#include "01_base/vec3v.h"

namespace rtk::RTK_ISA {

/// What a ray/triangle test finds for K triangles: per lane the distance and the barycentric
/// weights u and v of the triangle's second and third vertex. Only lanes of the returned mask
/// count.
template <int K>
struct TriangleHitsK {
  vfloat<K> t, u, v;
};

/// The Möller-Trumbore test in the form that reads a precomputed triangle: its first vertex v0,
/// its edges e1 = v1 - v0 and e2 = v2 - v0, and its geometric normal Ng = e1 x e2.
struct MoellerTrumbore {
  /// What the test keeps of a ray: nothing beyond the ray, broadcast to K lanes.
  template <int K>
  struct Precalc {
    Vec3v<K> org, dir;
    vfloat<K> tnear;
    explicit Precalc(const Ray& ray) : org(ray.org), dir(ray.dir), tnear(ray.tnear) {}
  };

  // [ch02-moeller]
  /// Tests K precomputed triangles; a lane hits when the ray crosses its triangle (either side)
  /// at a distance in [tnear, tfar]. Zero-area triangles (Ng = 0) and NaN lanes never hit.
  template <int K>
  static RTK_INLINE vbool<K> intersect(const Precalc<K>& ray, vfloat<K> tfar, const Vec3v<K>& v0,
                                       const Vec3v<K>& e1, const Vec3v<K>& e2, const Vec3v<K>& Ng,
                                       TriangleHitsK<K>& hit) {
    // The barycentric weights as scalar triple products of the edges, the direction and the
    // vector a from the origin to v0 (Cramer's rule on org + t dir = v0 + u e1 + v e2), all
    // scaled by the determinant den = Ng . dir. One cross product per ray and triangle.
    const Vec3v<K> a = v0 - ray.org;
    const Vec3v<K> r = cross(a, ray.dir);
    const vfloat<K> den = dot(Ng, ray.dir);
    const vfloat<K> abs_den = abs(den);
    // Two-sided: flip the scaled weights by the sign of den instead of dividing first.
    const vfloat<K> U = xorsign(dot(r, e2), den);
    const vfloat<K> V = xorsign(dot(r, e1), -den);
    // Inside when U >= 0, V >= 0 and U + V <= |den|; abs_den > 0 rejects zero area and NaN.
    vbool<K> valid = (abs_den > vfloat<K>(0.0f)) & (U >= vfloat<K>(0.0f)) &
                     (V >= vfloat<K>(0.0f)) & (U + V <= abs_den);
    if (none(valid)) return valid;
    // One exact division, so that every variant gets the same bits.
    const vfloat<K> inv = vfloat<K>(1.0f) / abs_den;
    const vfloat<K> t = xorsign(dot(a, Ng), den) * inv;
    // A tiny |den| can overflow the distance: a hit at infinity is no hit.
    valid = valid & (t >= ray.tnear) & (t <= tfar) & (abs(t) <= vfloat<K>(kMaxFloat));
    hit.t = t;
    hit.u = U * inv;
    hit.v = V * inv;
    return valid;
  }
  // [ch02-moeller]

  /// The same test on K triangles given by their vertices: the precomputation done per ray.
  /// It gives the same bits as the precomputed form, since the edges and normal are the same
  /// floating-point operations on the same inputs.
  template <int K>
  static RTK_INLINE vbool<K> intersect(const Precalc<K>& ray, vfloat<K> tfar, const Vec3v<K>& p0,
                                       const Vec3v<K>& p1, const Vec3v<K>& p2,
                                       TriangleHitsK<K>& hit) {
    const Vec3v<K> e1 = p1 - p0, e2 = p2 - p0;
    return intersect(ray, tfar, p0, e1, e2, cross(e1, e2), hit);
  }
};

}  // namespace rtk::RTK_ISA
