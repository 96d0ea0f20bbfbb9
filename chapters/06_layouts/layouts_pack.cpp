// Filling the leaf blocks of chapter 6's layouts: the precomputations each layout makes once,
// at build time, so that the tests make them never.
#include <array>
#include <stdexcept>
#include <string>

#include "06_layouts/triangle_i.h"
#include "06_layouts/triangle_m.h"
#include "06_layouts/triangle_v.h"
#include "02_bvh2/zero_area.h"

namespace rtk {

namespace {

/// The three vertices of a triangle as the layouts store them: a zero-area triangle becomes
/// three copies of its first vertex, which every intersector rejects with exact zeros.
struct Corners {
  Vec3f p[3];
  bool zero_area = false;

  Corners() = default;
  Corners(const TriangleMesh& mesh, uint32_t prim)
      : p{mesh.vertex(prim, 0), mesh.vertex(prim, 1), mesh.vertex(prim, 2)} {}
  /// Makes a zero-area triangle three copies of its first vertex.
  void flatten_if_zero_area() {
    if (!is_zero_area(p[0], p[1], p[2])) return;
    p[1] = p[2] = p[0];
    zero_area = true;
  }
};
Corners corners(const TriangleMesh& mesh, uint32_t prim) {
  Corners c(mesh, prim);
  c.flatten_if_zero_area();
  return c;
}

/// The entry of `prims` that lane `lane` of block `block` holds: unused lanes repeat lane 0.
uint32_t lane_prim(std::span<const uint32_t> prims, size_t block, int width, int lane) {
  const size_t i = block * size_t(width) + size_t(lane);
  return i < prims.size() ? prims[i] : prims[block * size_t(width)];
}

// [ch06-block-corners]
/// The corners of the M triangles of block `block`, as corners() makes them. A leaf names
/// triangles from all over the mesh, whose reads miss the caches: every lane's vertices are
/// read first and the zero-area tests come after, so that the misses of all lanes overlap.
template <int M>
std::array<Corners, M> block_corners(const TriangleMesh& mesh, std::span<const uint32_t> prims,
                                     size_t block) {
  std::array<Corners, M> c;
  for (int lane = 0; lane < M; ++lane) c[size_t(lane)] = Corners(mesh, lane_prim(prims, block, M, lane));
  for (Corners& lane : c) lane.flatten_if_zero_area();
  return c;
}
// [ch06-block-corners]

}  // namespace

template <int M>
void TriangleMLayout<M>::pack(const TriangleMesh& mesh, std::span<const uint32_t> prims, Block* out) {
  for (size_t b = 0; b < block_count(prims.size()); ++b) {
    Block& block = out[b];
    const std::array<Corners, M> all = block_corners<M>(mesh, prims, b);
    for (int lane = 0; lane < M; ++lane) {
      const uint32_t prim = lane_prim(prims, b, M, lane);
      const Corners& c = all[size_t(lane)];
      const Vec3f e1 = c.p[1] - c.p[0], e2 = c.p[2] - c.p[0];
      // The same float operations as the per-ray computation in 02_bvh2/moeller.h,
      // so precomputed and computed-per-ray tests give the same bits.
      const Vec3f ng = cross(e1, e2);
      for (int axis = 0; axis < 3; ++axis) {
        block.v0[axis][lane] = c.p[0][axis];
        block.e1[axis][lane] = e1[axis];
        block.e2[axis][lane] = e2[axis];
        block.Ng[axis][lane] = ng[axis];
      }
      block.prim[lane] = prim;
    }
  }
}

template struct TriangleMLayout<4>;
template struct TriangleMLayout<8>;

void Triangle1vLayout::pack(const TriangleMesh& mesh, std::span<const uint32_t> prims, Block* out) {
  for (size_t i = 0; i < prims.size(); ++i) {
    const Corners c = corners(mesh, prims[i]);
    out[i] = Triangle1v{c.p[0], prims[i], c.p[1], 0, c.p[2], 0};
  }
}

void Triangle4vLayout::pack(const TriangleMesh& mesh, std::span<const uint32_t> prims, Block* out) {
  for (size_t b = 0; b < block_count(prims.size()); ++b) {
    const std::array<Corners, 4> all = block_corners<4>(mesh, prims, b);
    for (int lane = 0; lane < 4; ++lane) {
      const Corners& c = all[size_t(lane)];
      for (int k = 0; k < 3; ++k)
        for (int axis = 0; axis < 3; ++axis) out[b].p[k][axis][lane] = c.p[k][axis];
      out[b].prim[lane] = lane_prim(prims, b, 4, lane);
    }
  }
}

void Triangle1iLayout::pack(const TriangleMesh& mesh, std::span<const uint32_t> prims, Block* out) {
  for (size_t i = 0; i < prims.size(); ++i) {
    const auto& tri = mesh.triangles[prims[i]];
    const bool flat = corners(mesh, prims[i]).zero_area;
    out[i] = Triangle1i{{tri[0], flat ? tri[0] : tri[1], flat ? tri[0] : tri[2]}, prims[i],
                        mesh.vertices.data(), 0};
  }
}

void Triangle4iLayout::pack(const TriangleMesh& mesh, std::span<const uint32_t> prims, Block* out) {
  if (mesh.vertices.size() > kMaxIndexedVertices)
    throw std::invalid_argument("triangle4i: a mesh of " + std::to_string(mesh.vertices.size()) +
                                " vertices is more than the " + std::to_string(kMaxIndexedVertices) +
                                " an indexed block can address");
  for (size_t b = 0; b < block_count(prims.size()); ++b) {
    const std::array<Corners, 4> all = block_corners<4>(mesh, prims, b);
    for (int lane = 0; lane < 4; ++lane) {
      const uint32_t prim = lane_prim(prims, b, 4, lane);
      const auto& tri = mesh.triangles[prim];
      const bool flat = all[size_t(lane)].zero_area;
      for (int k = 0; k < 3; ++k) out[b].v[k][lane] = int32_t(flat ? tri[0] : tri[size_t(k)]);
      out[b].prim[lane] = prim;
    }
    out[b].vertices = mesh.vertices.data();
    out[b].unused = 0;
  }
}

}  // namespace rtk
