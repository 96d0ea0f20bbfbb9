/// \file
/// Precomputed triangles in blocks of M (the guide's triangle4 and triangle8): what the
/// Möller-Trumbore test reads with no arithmetic spent on the triangle. The guide's triangle1
/// is chapter 2's Triangle1 (02_bvh2/triangle1.h).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "01_base/triangle_mesh.h"

namespace rtk {

// [ch06-triangle-m]
/// M triangles in structure-of-arrays form, each as its first vertex v0, its edges
/// e1 = p1 - p0 and e2 = p2 - p0 and its normal Ng = e1 x e2: component c of vector X of
/// triangle i is X[c][i], so one aligned load brings one component of all M. 12 floats and a
/// primID per triangle: 52 bytes, the most of any layout, and the least work per test.
/// Unused lanes repeat lane 0 (a duplicate hit changes nothing); a zero-area triangle is
/// stored with zero edges and normal, which no test can hit.
template <int M>
struct alignas(M >= 8 ? 32 : 16) TriangleM {
  float v0[3][M];
  float e1[3][M];
  float e2[3][M];
  float Ng[3][M];
  uint32_t prim[M];
};
static_assert(sizeof(TriangleM<4>) == 208, "13 rows of four: 52 bytes per triangle");
static_assert(sizeof(TriangleM<8>) == 416, "13 rows of eight: 52 bytes per triangle");
// [ch06-triangle-m]

/// The triangle4 (M = 4) and triangle8 (M = 8) leaf layouts (LeafLayout in 02_bvh2/node_ref.h).
template <int M>
struct TriangleMLayout {
  static constexpr std::string_view kName = M == 4 ? "triangle4" : "triangle8";
  static constexpr int kWidth = M;
  using Block = TriangleM<M>;
  static size_t block_count(size_t triangles) { return (triangles + M - 1) / M; }
  /// Fills block_count(prims.size()) blocks with the triangles `prims`, in order.
  static void pack(const TriangleMesh& mesh, std::span<const uint32_t> prims, Block* out);
};

using Triangle4Layout = TriangleMLayout<4>;
using Triangle8Layout = TriangleMLayout<8>;

extern template struct TriangleMLayout<4>;
extern template struct TriangleMLayout<8>;

}  // namespace rtk
