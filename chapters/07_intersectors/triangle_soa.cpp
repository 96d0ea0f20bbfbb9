#include "07_intersectors/triangle_soa.h"

#include <limits>
#include <stdexcept>
#include <string>

#include "02_bvh2/zero_area.h"

namespace rtk {

TriangleSoA::TriangleSoA(const TriangleMesh& mesh) : count(mesh.size()) {
  const size_t padded = (count + kPadding - 1) / kPadding * kPadding;
  for (auto& array : coords) array.assign(padded, std::numeric_limits<float>::quiet_NaN());
  for (size_t i = 0; i < count; ++i) {
    for (const uint32_t index : mesh.triangles[i])
      if (index >= mesh.vertices.size())
        throw std::invalid_argument("triangle " + std::to_string(i) + " has vertex index " +
                                    std::to_string(index) + ", but the mesh has only " +
                                    std::to_string(mesh.vertices.size()) + " vertices");
    Vec3f p[3] = {mesh.vertex(uint32_t(i), 0), mesh.vertex(uint32_t(i), 1), mesh.vertex(uint32_t(i), 2)};
    if (is_zero_area(p[0], p[1], p[2])) p[1] = p[2] = p[0];
    for (int k = 0; k < 3; ++k)
      for (int axis = 0; axis < 3; ++axis) coords[size_t(3 * k + axis)][i] = p[k][axis];
  }
}

}  // namespace rtk
