#include "02_bvh2/triangle1.h"

#include "02_bvh2/zero_area.h"

namespace rtk {

void Triangle1Layout::pack(const TriangleMesh& mesh, std::span<const uint32_t> prims, Triangle1* out) {
  for (size_t i = 0; i < prims.size(); ++i) {
    const uint32_t prim = prims[i];
    const Vec3f p0 = mesh.vertex(prim, 0), p1 = mesh.vertex(prim, 1), p2 = mesh.vertex(prim, 2);
    Triangle1& t = out[i];
    t = Triangle1{p0, prim, p1 - p0, 0, p2 - p0, 0};
    // Collinear vertices can give float edges that are not exactly parallel, and then a tiny
    // but non-zero determinant: zero the edges so that the determinant is exactly zero.
    if (is_zero_area(p0, p1, p2)) t.e1 = t.e2 = Vec3f(0.0f);
  }
}

}  // namespace rtk
