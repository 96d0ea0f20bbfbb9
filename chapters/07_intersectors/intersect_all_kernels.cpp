// Chapter 7's brute-force kernels, compiled once per ISA (see intersect_all.h).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "07_intersectors/intersect_all.h"
#include "02_bvh2/moeller.h"
#include "07_intersectors/pluecker.h"
#include "07_intersectors/watertight.h"

namespace rtk::RTK_ISA {

namespace {

// [ch07-closest-in-block]
/// One ray against all triangles, K at a time. After a hit the interval's far end moves to
/// just below the hit distance, so later triangles must be strictly closer: equal distances
/// keep the lowest primID, whatever K is.
template <class Intersector, int K>
Hit closest_hit(const TriangleSoA& tris, const Ray& ray) {
  Hit best;
  if (!is_valid(ray)) return best;
  const typename Intersector::template Precalc<K> pre(ray);
  float tfar = ray.tfar;
  for (size_t first = 0; first < tris.padded_count(); first += K) {
    const Vec3v<K> p0 = Vec3v<K>::load(tris.coord(0, 0), tris.coord(0, 1), tris.coord(0, 2), first);
    const Vec3v<K> p1 = Vec3v<K>::load(tris.coord(1, 0), tris.coord(1, 1), tris.coord(1, 2), first);
    const Vec3v<K> p2 = Vec3v<K>::load(tris.coord(2, 0), tris.coord(2, 1), tris.coord(2, 2), first);
    TriangleHitsK<K> hits;
    const vbool<K> valid = Intersector::intersect(pre, vfloat<K>(tfar), p0, p1, p2, hits);
    if (none(valid)) continue;
    // The nearest valid lane, the lowest one among equals.
    const vfloat<K> t = select(valid, hits.t, vfloat<K>(std::numeric_limits<float>::infinity()));
    const int lane = bit_scan_forward(movemask(valid & (t == vfloat<K>(reduce_min(t)))));
    best = {hits.t[lane], hits.u[lane], hits.v[lane], uint32_t(first + size_t(lane))};
    tfar = std::nextafter(best.t, -std::numeric_limits<float>::infinity());
  }
  return best;
}
// [ch07-closest-in-block]

template <class Intersector, int K>
void run(const TriangleSoA& tris, std::span<const Ray> rays, std::span<Hit> hits) {
  for (size_t i = 0; i < rays.size(); ++i) hits[i] = closest_hit<Intersector, K>(tris, rays[i]);
}

template <int K>
void run_kind(const TriangleSoA& tris, IntersectorKind kind, std::span<const Ray> rays, std::span<Hit> hits) {
  switch (kind) {
    case IntersectorKind::moeller: return run<MoellerTrumbore, K>(tris, rays, hits);
    case IntersectorKind::pluecker: return run<PlueckerStable, K>(tris, rays, hits);
    case IntersectorKind::watertight: return run<Watertight, K>(tris, rays, hits);
  }
  throw std::invalid_argument("intersect_all: unknown intersector");
}

}  // namespace

void intersect_all(const TriangleSoA& tris, IntersectorKind kind, int width,
                   std::span<const Ray> rays, std::span<Hit> hits) {
  if (rays.size() != hits.size())
    throw std::invalid_argument("intersect_all: " + std::to_string(rays.size()) + " rays but " +
                                std::to_string(hits.size()) + " hits");
  switch (width) {
    case 1: return run_kind<1>(tris, kind, rays, hits);
    case 4: return run_kind<4>(tris, kind, rays, hits);
    case 8: return run_kind<8>(tris, kind, rays, hits);
    case 16: return run_kind<16>(tris, kind, rays, hits);
  }
  throw std::invalid_argument("intersect_all: width " + std::to_string(width) +
                              " is not one of 1, 4, 8, 16");
}

}  // namespace rtk::RTK_ISA
