/// \file
/// The indexed triangle set: what every builder takes as input.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "01_base/box3.h"

namespace rtk {

/// Triangles as indices into a shared vertex array. Triangle i has primID i; its vertices are
/// p0, p1, p2 in the order of `triangles[i]`, and the barycentric weights u and v of a hit
/// belong to p1 and p2.
struct TriangleMesh {
  std::vector<Vec3f> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;

  size_t size() const { return triangles.size(); }
  Vec3f vertex(uint32_t prim, int corner) const { return vertices[triangles[prim][corner]]; }
  Box3f bounds(uint32_t prim) const {
    return Box3f(vertex(prim, 0)).extend(vertex(prim, 1)).extend(vertex(prim, 2));
  }
  Box3f bounds() const {
    Box3f box;
    for (const Vec3f& v : vertices) box.extend(v);
    return box;
  }
};

}  // namespace rtk
