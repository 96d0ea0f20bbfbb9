#include "14_pathtracer/scene.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rtk {

uint32_t RenderScene::add_material(Material material) {
  materials.push_back(std::move(material));
  return static_cast<uint32_t>(materials.size() - 1);
}

void RenderScene::add_light(std::shared_ptr<const Light> light) {
  if (!light) throw std::invalid_argument("add_light: null light");
  lights.push_back(std::move(light));
}

void RenderScene::add_area_light(std::span<const std::shared_ptr<const TriangleLight>> triangles,
                                 Color radiance) {
  Material m;
  m.name = "light";
  m.prototype = Lambertian{Color(0.0f)};
  m.emission = radiance;
  const uint32_t material = add_material(std::move(m));
  for (const auto& t : triangles) add_triangle_light(t, material);
}

uint32_t RenderScene::add_triangle_light(std::shared_ptr<const TriangleLight> light,
                                         uint32_t material) {
  if (!light) throw std::invalid_argument("add_triangle_light: null light");
  const uint32_t first = static_cast<uint32_t>(mesh.vertices.size());
  // The mesh keeps the light's vertex order, so that barycentrics and normals agree with it.
  for (const Vec3f& v : light->vertices()) {
    mesh.vertices.push_back(v);
    if (has_motion()) vertices_t1.push_back(v);
  }
  if (!normals.empty()) normals.insert(normals.end(), 3, Vec3f(0.0f));
  if (!uvs.empty()) uvs.insert(uvs.end(), 3, Vec2f{});
  mesh.triangles.push_back({first, first + 1, first + 2});
  triangle_material.push_back(material);
  lights.push_back(light);
  triangle_light.push_back(static_cast<int32_t>(lights.size() - 1));
  return static_cast<uint32_t>(mesh.triangles.size() - 1);
}

bool RenderScene::has_transparency() const {
  for (const Material& m : materials)
    if (m.transparent()) return true;
  return false;
}

std::array<Vec3f, 3> RenderScene::corners(uint32_t prim, float time) const {
  const auto& tri = mesh.triangles[prim];
  std::array<Vec3f, 3> c;
  for (int k = 0; k < 3; ++k) {
    c[k] = mesh.vertices[tri[k]];
    if (has_motion()) c[k] = c[k] + (vertices_t1[tri[k]] - c[k]) * time;
  }
  return c;
}

// [ch14-tangents]
void RenderScene::texture_tangents(uint32_t prim, const std::array<Vec3f, 3>& c, Vec3f& dpdu,
                                   Vec3f& dpdv) const {
  const Vec3f e1 = c[1] - c[0], e2 = c[2] - c[0];
  dpdu = e1, dpdv = e2;  // without uvs, (u, v) are the barycentrics
  if (uvs.empty()) return;
  // The edges in texture space and in space are related by one linear map:
  // e1 = du1 dpdu + dv1 dpdv, e2 = du2 dpdu + dv2 dpdv; solve it for dpdu and dpdv.
  const auto& tri = mesh.triangles[prim];
  const Vec2f d1 = uvs[tri[1]] - uvs[tri[0]], d2 = uvs[tri[2]] - uvs[tri[0]];
  const float det = d1.x * d2.y - d1.y * d2.x;
  if (!(std::fabs(det) > 1e-12f)) return;  // degenerate texture coordinates: the edges
  const float r = 1.0f / det;
  dpdu = (e1 * d2.y - e2 * d1.y) * r;
  dpdv = (e2 * d1.x - e1 * d2.x) * r;
}
// [ch14-tangents]

void RenderScene::validate() const {
  const size_t nv = mesh.vertices.size(), nt = mesh.triangles.size();
  auto fail = [](const std::string& what) { throw std::invalid_argument("render scene: " + what); };
  if (!vertices_t1.empty() && vertices_t1.size() != nv)
    fail("vertices_t1 has " + std::to_string(vertices_t1.size()) + " entries for " +
         std::to_string(nv) + " vertices");
  if (!normals.empty() && normals.size() != nv) fail("normals do not match the vertices");
  if (!uvs.empty() && uvs.size() != nv) fail("uvs do not match the vertices");
  if (triangle_material.size() != nt) fail("triangle_material does not match the triangles");
  if (triangle_light.size() != nt) fail("triangle_light does not match the triangles");
  for (const Vec3f& v : mesh.vertices)
    if (!is_finite(v)) fail("a vertex is not finite");
  for (const Vec3f& v : vertices_t1)
    if (!is_finite(v)) fail("a vertex at time 1 is not finite");
  for (size_t i = 0; i < nt; ++i) {
    for (uint32_t index : mesh.triangles[i])
      if (index >= nv) fail("triangle " + std::to_string(i) + " has a vertex index out of range");
    if (triangle_material[i] >= materials.size())
      fail("triangle " + std::to_string(i) + " has a material index out of range");
    const int32_t light = triangle_light[i];
    if (light == kNoLight) continue;
    if (light < 0 || static_cast<size_t>(light) >= lights.size())
      fail("triangle " + std::to_string(i) + " has a light index out of range");
    if (!dynamic_cast<const TriangleLight*>(lights[light].get()))
      fail("triangle " + std::to_string(i) + " names a light that is not a TriangleLight");
  }
  for (const auto& light : lights)
    if (!light) fail("a light is null");
}

}  // namespace rtk
