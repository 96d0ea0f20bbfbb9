/// \file
/// All triangles of a mesh as nine float arrays: the input of the brute-force kernels that the
/// intersectors are tested and measured with, before any acceleration structure is involved.
#pragma once

#include <array>
#include <cstddef>

#include "01_base/aligned.h"
#include "01_base/triangle_mesh.h"

namespace rtk {

/// The vertices of every triangle in structure-of-arrays form: coord(k, axis)[i] is the `axis`
/// component of vertex k of triangle i. Zero-area triangles (is_zero_area) are stored as three
/// copies of their first vertex; the arrays are padded to a multiple of 16 with NaN, which no
/// intersector ever reports as a hit, and start on a cache line.
struct TriangleSoA {
  static constexpr size_t kPadding = 16;

  size_t count = 0;                          ///< the number of triangles (primIDs 0..count-1)
  std::array<aligned_vector<float>, 9> coords;  ///< vertex k, axis a at index 3 k + a

  TriangleSoA() = default;
  /// Transposes the mesh's triangles; throws std::invalid_argument for a vertex index out of
  /// range.
  explicit TriangleSoA(const TriangleMesh& mesh);

  /// The number of entries including the padding.
  size_t padded_count() const { return coords[0].size(); }
  const float* coord(int vertex, int axis) const { return coords[size_t(3 * vertex + axis)].data(); }
};

}  // namespace rtk
