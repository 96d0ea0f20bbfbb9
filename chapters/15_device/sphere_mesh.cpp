#include "15_device/sphere_mesh.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rtk {

SphereMesh tessellate_sphere(Vec3f centre, float radius, int num_theta, int num_phi) {
  if (!(radius > 0.0f) || !std::isfinite(radius))
    throw std::invalid_argument("sphere: the radius must be positive and finite (got " +
                                std::to_string(radius) + ")");
  if (num_theta < 2 || num_theta > 4096)
    throw std::invalid_argument("sphere: numTheta must be in [2, 4096] (got " + std::to_string(num_theta) + ")");
  if (num_phi < 3 || num_phi > 4096)
    throw std::invalid_argument("sphere: numPhi must be in [3, 4096] (got " + std::to_string(num_phi) + ")");
  if (!std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(centre.z))
    throw std::invalid_argument("sphere: the centre must be finite");
  constexpr float pi = std::numbers::pi_v<float>;
  SphereMesh m;
  m.vertices.reserve(static_cast<size_t>(num_theta + 1) * num_phi);
  m.normals.reserve(m.vertices.capacity());
  for (int i = 0; i <= num_theta; ++i)
    for (int j = 0; j < num_phi; ++j) {
      const float theta = i * pi / num_theta, phi = j * 2.0f * pi / num_phi;
      const Vec3f d{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
      m.vertices.push_back(centre + d * radius);
      m.normals.push_back(d);
    }
  auto at = [&](int i, int j) { return static_cast<uint32_t>(i * num_phi + (j % num_phi)); };
  // The pole rings would give degenerate triangles: the first and last ring get one triangle
  // per quad, the others two. Each is wound so that its geometric normal points outward, as
  // the vertex normals do: the renderer turns a shading normal to the geometric normal's
  // side, and a glass sphere wound inward would refract as if its inside were outside.
  for (int i = 1; i <= num_theta; ++i)
    for (int j = 1; j <= num_phi; ++j) {
      if (i > 1) m.triangles.push_back({at(i, j - 1), at(i - 1, j - 1), at(i - 1, j)});
      if (i < num_theta) m.triangles.push_back({at(i, j), at(i, j - 1), at(i - 1, j)});
    }
  return m;
}

}  // namespace rtk
