/// \file
/// The tessellated sphere of the Embree 1.1 scene formats (the XML `<Sphere>` and the guide's
/// -trisphere): rings of latitude and longitude, with the pole vertices repeated once per
/// longitude so that every ring has the same number of vertices.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "01_base/vec3.h"

namespace rtk {

/// A tessellated sphere: positions, unit normals and triangles (counter-clockwise seen from
/// outside).
struct SphereMesh {
  std::vector<Vec3f> vertices;  ///< (num_theta + 1) * num_phi positions
  std::vector<Vec3f> normals;   ///< the unit direction from the centre of each vertex
  std::vector<std::array<uint32_t, 3>> triangles;  ///< 2 * num_phi * (num_theta - 1) triangles
};

/// Tessellates a sphere as Embree 1.1 does: vertex (i, j) = centre + radius * (sin t cos p,
/// cos t, sin t sin p) with t = i pi / num_theta and p = 2 pi j / num_phi. Throws
/// std::invalid_argument for a radius that is not positive and finite, num_theta below 2 or
/// num_phi below 3 (or either above 4096).
SphereMesh tessellate_sphere(Vec3f centre, float radius, int num_theta, int num_phi);

}  // namespace rtk
