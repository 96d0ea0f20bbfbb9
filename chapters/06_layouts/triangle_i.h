/// \file
/// Triangles stored as indices into the mesh's shared vertex array (the guide's triangle1i
/// and triangle4i): the least memory, since a vertex that six triangles share is stored once,
/// and the most work per test, since the vertices are fetched through the indices.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "01_base/triangle_mesh.h"

namespace rtk {

// [ch06-triangle-i]
/// One triangle as three vertex indices and its primID, with the address of the vertex array.
/// The address is there because the traversal hands a leaf intersector nothing but the ray
/// and the block: 16 bytes of indices would do, and 32 is what the pointer costs.
struct alignas(16) Triangle1i {
  uint32_t v[3];
  uint32_t prim;
  const Vec3f* vertices;
  uint64_t unused;
};
static_assert(sizeof(Triangle1i) == 32, "indices and primID, then the vertex array's address");

/// M triangles as vertex indices: v[k][i] is the index of vertex k of triangle i, ready for a
/// gather (as a float offset, 3 v, it must fit an int32: meshes of up to 715 million vertices).
/// 20 bytes per triangle for M = 4, plus the shared vertices (12 bytes each, about half a
/// vertex per triangle in a closed mesh). Unused lanes repeat lane 0.
template <int M>
struct alignas(16) TriangleMi {
  int32_t v[3][M];
  uint32_t prim[M];
  const Vec3f* vertices;
  uint64_t unused;
};
static_assert(sizeof(TriangleMi<4>) == 80, "four rows of four, then the vertex array's address");
// [ch06-triangle-i]

/// The most vertices an indexed layout can address (3 v must fit an int32).
inline constexpr size_t kMaxIndexedVertices = 0x7FFFFFFF / 3;

/// The triangle1i leaf layout. The blocks point into `mesh.vertices`, which must outlive them
/// (LayoutBVH keeps its own copy of the mesh for this).
struct Triangle1iLayout {
  static constexpr std::string_view kName = "triangle1i";
  static constexpr int kWidth = 1;
  using Block = Triangle1i;
  static size_t block_count(size_t triangles) { return triangles; }
  /// Fills one block per entry of `prims`; a zero-area triangle gets three copies of its first index.
  static void pack(const TriangleMesh& mesh, std::span<const uint32_t> prims, Block* out);
};

/// The triangle4i leaf layout: blocks of four, pointing into `mesh.vertices` like triangle1i.
struct Triangle4iLayout {
  static constexpr std::string_view kName = "triangle4i";
  static constexpr int kWidth = 4;
  using Block = TriangleMi<4>;
  static size_t block_count(size_t triangles) { return (triangles + 3) / 4; }
  /// Fills block_count(prims.size()) blocks. Throws std::invalid_argument for a mesh with more
  /// than kMaxIndexedVertices vertices.
  static void pack(const TriangleMesh& mesh, std::span<const uint32_t> prims, Block* out);
};

}  // namespace rtk
