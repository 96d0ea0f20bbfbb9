/// \file
/// Triangles stored as their three vertices (the guide's triangle1v and triangle4v): what the
/// Plücker and watertight tests read, and Möller-Trumbore too, at the price of computing the
/// edges per ray.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "01_base/triangle_mesh.h"

namespace rtk {

// [ch06-triangle-v]
/// One triangle as three vertices and its primID: 48 bytes, three 16-byte rows.
struct alignas(16) Triangle1v {
  Vec3f p0;
  uint32_t prim;
  Vec3f p1;
  uint32_t unused0;
  Vec3f p2;
  uint32_t unused1;
};
static_assert(sizeof(Triangle1v) == 48, "three 16-byte rows");

/// M triangles as vertices in structure-of-arrays form: p[k][c][i] is component c of vertex k
/// of triangle i. 9 floats and a primID per triangle: 40 bytes. Unused lanes repeat lane 0.
template <int M>
struct alignas(16) TriangleMv {
  float p[3][3][M];
  uint32_t prim[M];
};
static_assert(sizeof(TriangleMv<4>) == 160, "10 rows of four: 40 bytes per triangle");
// [ch06-triangle-v]

/// The triangle1v leaf layout: one Triangle1v per triangle.
struct Triangle1vLayout {
  static constexpr std::string_view kName = "triangle1v";
  static constexpr int kWidth = 1;
  using Block = Triangle1v;
  static size_t block_count(size_t triangles) { return triangles; }
  /// Fills one block per entry of `prims`; a zero-area triangle gets three copies of p0.
  static void pack(const TriangleMesh& mesh, std::span<const uint32_t> prims, Block* out);
};

/// The triangle4v leaf layout: blocks of four.
struct Triangle4vLayout {
  static constexpr std::string_view kName = "triangle4v";
  static constexpr int kWidth = 4;
  using Block = TriangleMv<4>;
  static size_t block_count(size_t triangles) { return (triangles + 3) / 4; }
  /// Fills block_count(prims.size()) blocks; a zero-area triangle gets three copies of p0.
  static void pack(const TriangleMesh& mesh, std::span<const uint32_t> prims, Block* out);
};

}  // namespace rtk
