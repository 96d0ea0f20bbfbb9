/// \file
/// The stable Plücker ray/triangle test for one ray against K triangles: edge functions that
/// two triangles sharing an edge compute identically, so no ray slips between them.
///
/// The edge test is the Plücker-coordinate side test of Amanatides and Choi ("Ray tracing
/// triangular meshes", 1995; see also Shevtsov, Soupikov and Kapustin, "Ray-triangle
/// intersection algorithm for modern CPU architectures", GraphiCon 2007), evaluated on vertices
/// made relative to the ray origin, in the arrangement Embree calls the stable Plücker test.
#pragma once

#include "01_base/ray.h"
#include "02_bvh2/moeller.h"  // TriangleHitsK

namespace rtk::RTK_ISA {

/// The stable Plücker test on triangles given by their three vertices.
struct PlueckerStable {
  /// What the test keeps of a ray: the ray broadcast to K lanes.
  template <int K>
  struct Precalc {
    Vec3v<K> org, dir;
    vfloat<K> tnear;
    explicit Precalc(const Ray& ray) : org(ray.org), dir(ray.dir), tnear(ray.tnear) {}
  };

  // [ch07-pluecker-edge]
  /// The edge function of the directed edge x -> y, for vertices x and y relative to the ray
  /// origin: dir . ((y - x) x (y + x)), which is 2 dir . (y x x), the signed volume the ray
  /// spans with the edge. It depends on nothing but the edge's two endpoints, and for the
  /// reversed edge y -> x every step is negated exactly (x - y = -(y - x) and x + y = y + x in
  /// floating point, and cross and dot are sign-symmetric), so the two triangles on either side
  /// of an edge see exactly opposite values: one of them always claims the ray.
  template <int K>
  static RTK_INLINE vfloat<K> edge_function(const Vec3v<K>& x, const Vec3v<K>& y, const Vec3v<K>& dir) {
    return dot(cross(y - x, y + x), dir);
  }
  // [ch07-pluecker-edge]

  // [ch07-pluecker]
  /// Tests K triangles (p0, p1, p2); a lane hits when the ray crosses its triangle (either side)
  /// at a distance in [tnear, tfar]. Zero-area triangles and NaN lanes never hit.
  template <int K>
  static RTK_INLINE vbool<K> intersect(const Precalc<K>& ray, vfloat<K> tfar, const Vec3v<K>& p0,
                                       const Vec3v<K>& p1, const Vec3v<K>& p2,
                                       TriangleHitsK<K>& hit) {
    // Vertices relative to the ray origin: each vertex is rounded once, the same way for
    // every triangle that holds it.
    const Vec3v<K> a = p0 - ray.org, b = p1 - ray.org, c = p2 - ray.org;
    // One edge function per edge, cyclic order; each is the weight of the opposite vertex.
    const vfloat<K> w0 = edge_function(b, c, ray.dir);
    const vfloat<K> w1 = edge_function(c, a, ray.dir);
    const vfloat<K> w2 = edge_function(a, b, ray.dir);
    // Inside when all three have one sign (zero counts as either: a ray through an edge hits
    // both triangles). Written positively so that NaN fails both tests.
    const vfloat<K> zero(0.0f);
    vbool<K> valid = ((w0 >= zero) & (w1 >= zero) & (w2 >= zero)) |
                     ((w0 <= zero) & (w1 <= zero) & (w2 <= zero));
    if (none(valid)) return valid;
    // Distance from the plane through a with the normal of the edges a - c and b - a.
    const Vec3v<K> Ng = cross(a - c, b - a);
    const vfloat<K> den = dot(Ng, ray.dir);
    const vfloat<K> sum = w0 + w1 + w2;
    valid = valid & (abs(den) > zero) & (abs(sum) > zero);
    const vfloat<K> t = dot(a, Ng) / den;
    valid = valid & (t >= ray.tnear) & (t <= tfar) & (abs(t) <= vfloat<K>(kMaxFloat));
    const vfloat<K> inv = vfloat<K>(1.0f) / sum;
    hit.t = t;
    hit.u = w1 * inv;
    hit.v = w2 * inv;
    return valid;
  }
  // [ch07-pluecker]
};

}  // namespace rtk::RTK_ISA
