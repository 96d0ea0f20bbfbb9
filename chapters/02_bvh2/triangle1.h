/// \file
/// The leaf layout of chapters 2 and 3: one precomputed triangle per block, ready for a plain
/// Möller-Trumbore test. Chapter 6 compares it with the other layouts of the guide.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "01_base/triangle_mesh.h"
#include "01_base/vec3.h"

namespace rtk {

// [ch02-triangle1]
/// A triangle as Möller and Trumbore's test wants it ("Fast, minimum storage ray-triangle
/// intersection", JGT 1997): the first vertex and the two edges leaving it, so that the test
/// does no subtraction of vertices. 48 bytes: three 16-byte rows, the primID in the first.
/// A triangle of zero area (is_zero_area) is stored with zero edges, which the test can never
/// hit.
struct alignas(16) Triangle1 {
  Vec3f v0;
  uint32_t prim;
  Vec3f e1;  ///< p1 - p0: the barycentric u grows along it
  uint32_t unused0;
  Vec3f e2;  ///< p2 - p0: the barycentric v grows along it
  uint32_t unused1;
};
static_assert(sizeof(Triangle1) == 48, "three 16-byte rows");
// [ch02-triangle1]

/// The Triangle1 leaf layout (see LeafLayout in node_ref.h): one block per triangle.
struct Triangle1Layout {
  static constexpr std::string_view kName = "triangle1";
  using Block = Triangle1;
  static size_t block_count(size_t triangles) { return triangles; }
  /// Fills one Triangle1 per entry of `prims`.
  static void pack(const TriangleMesh& mesh, std::span<const uint32_t> prims, Triangle1* out);
};

}  // namespace rtk
