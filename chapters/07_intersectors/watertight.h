/// \file
/// The watertight ray/triangle test for one ray against K triangles.
///
/// Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", Journal of Computer
/// Graphics Techniques 2(1), 2013. The ray is made the +z axis of a sheared coordinate system;
/// the triangle is projected into the xy plane there, and the 2D edge functions of the origin
/// decide the hit. Their signs are exact: where a float edge function comes out zero, it is
/// recomputed in double precision, where the products of floats are exact (section 3 of the
/// paper). With exact signs on vertices that every triangle transforms the same way, no ray
/// slips through an edge or a vertex of a closed mesh.
#pragma once

#include <cstdint>
#include <utility>

#include "01_base/ray.h"
#include "02_bvh2/moeller.h"  // TriangleHitsK

namespace rtk::RTK_ISA {

/// The watertight test on triangles given by their three vertices.
struct Watertight {
  // [ch07-watertight-precalc]
  /// The ray's shear transform, computed once per ray: kz is the axis of the direction's
  /// largest magnitude, kx and ky the other two (swapped when dir[kz] < 0, so that the
  /// transform keeps the triangles' winding), and the shear maps dir to (0, 0, 1).
  template <int K>
  struct Precalc {
    Vec3v<K> org;
    vfloat<K> tnear;
    int kx, ky, kz;
    vfloat<K> sx, sy, sz;
    explicit Precalc(const Ray& ray) : org(ray.org), tnear(ray.tnear) {
      const Vec3f d = ray.dir;
      kz = max_axis(abs(d));
      kx = kz == 2 ? 0 : kz + 1;
      ky = kx == 2 ? 0 : kx + 1;
      if (d[kz] < 0.0f) std::swap(kx, ky);
      sx = vfloat<K>(d[kx] / d[kz]);
      sy = vfloat<K>(d[ky] / d[kz]);
      sz = vfloat<K>(1.0f / d[kz]);
    }
  };
  // [ch07-watertight-precalc]

  // [ch07-watertight-fallback]
  /// Recomputes in double precision the lanes where a float edge function came out zero. The
  /// products of two floats are exact in double, so their difference has the exact sign (zero
  /// only when the edge passes exactly through the ray), and that is all the test needs.
  template <int K>
  [[gnu::noinline]] static void recompute_in_double(uint32_t lanes, const vfloat<K> (&x)[3],
                                               const vfloat<K> (&y)[3], vfloat<K>& U,
                                               vfloat<K>& V, vfloat<K>& W) {
    alignas(64) float xs[3][K], ys[3][K], out[3][K];
    for (int i = 0; i < 3; ++i) x[i].storeu(xs[i]), y[i].storeu(ys[i]);
    U.storeu(out[0]), V.storeu(out[1]), W.storeu(out[2]);
    for (const int l : set_bits(lanes)) {
      // Edge (b, c) gives U, (c, a) gives V, (a, b) gives W: e(p, q) = q.x p.y - q.y p.x.
      for (int e = 0; e < 3; ++e) {
        const int p = (e + 1) % 3, q = (e + 2) % 3;
        out[e][l] = float(double(xs[q][l]) * double(ys[p][l]) - double(ys[q][l]) * double(xs[p][l]));
      }
    }
    U = vfloat<K>::loadu(out[0]), V = vfloat<K>::loadu(out[1]), W = vfloat<K>::loadu(out[2]);
  }
  // [ch07-watertight-fallback]

  // [ch07-watertight]
  /// Tests K triangles (p0, p1, p2); a lane hits when the ray crosses its triangle (either side)
  /// at a distance in [tnear, tfar]. Zero-area triangles and NaN lanes never hit.
  template <int K>
  static RTK_INLINE vbool<K> intersect(const Precalc<K>& ray, vfloat<K> tfar, const Vec3v<K>& p0,
                                       const Vec3v<K>& p1, const Vec3v<K>& p2,
                                       TriangleHitsK<K>& hit) {
    // Translate to the ray origin, then shear: x' = x - sx z, y' = y - sy z. Each vertex is
    // transformed by itself, so neighbouring triangles see the same projected vertex.
    const Vec3v<K> a = p0 - ray.org, b = p1 - ray.org, c = p2 - ray.org;
    const vfloat<K> az = a[ray.kz], bz = b[ray.kz], cz = c[ray.kz];
    const vfloat<K> x[3] = {a[ray.kx] - ray.sx * az, b[ray.kx] - ray.sx * bz, c[ray.kx] - ray.sx * cz};
    const vfloat<K> y[3] = {a[ray.ky] - ray.sy * az, b[ray.ky] - ray.sy * bz, c[ray.ky] - ray.sy * cz};
    // 2D edge functions of the origin, one per edge; each is the weight of the opposite vertex.
    vfloat<K> U = x[2] * y[1] - y[2] * x[1];
    vfloat<K> V = x[0] * y[2] - y[0] * x[2];
    vfloat<K> W = x[1] * y[0] - y[1] * x[0];
    const vfloat<K> zero(0.0f);
    const uint32_t exact_zero = movemask((U == zero) | (V == zero) | (W == zero));
    if (RTK_UNLIKELY(exact_zero != 0)) recompute_in_double(exact_zero, x, y, U, V, W);
    // Inside when the three have one sign; zero counts as either. NaN fails both tests.
    vbool<K> valid = ((U >= zero) & (V >= zero) & (W >= zero)) |
                     ((U <= zero) & (V <= zero) & (W <= zero));
    if (none(valid)) return valid;
    const vfloat<K> det = U + V + W;
    valid = valid & (abs(det) > zero);
    // The scaled distance: the barycentric blend of the vertices' sheared z.
    const vfloat<K> T = U * (ray.sz * az) + V * (ray.sz * bz) + W * (ray.sz * cz);
    const vfloat<K> inv = vfloat<K>(1.0f) / det;
    const vfloat<K> t = T * inv;
    valid = valid & (t >= ray.tnear) & (t <= tfar) & (abs(t) <= vfloat<K>(kMaxFloat));
    hit.t = t;
    hit.u = V * inv;
    hit.v = W * inv;
    return valid;
  }
  // [ch07-watertight]
};

}  // namespace rtk::RTK_ISA
