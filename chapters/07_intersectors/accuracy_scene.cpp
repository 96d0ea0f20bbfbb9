#include "07_intersectors/accuracy_scene.h"

#include <cmath>
#include <numbers>

#include "07_intersectors/stability_meshes.h"

namespace rtk {

namespace {

struct Vec3d {
  double x, y, z;
};
Vec3d to_double(Vec3f v) { return {v.x, v.y, v.z}; }
Vec3d operator-(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3d operator+(Vec3d a, Vec3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3d operator*(Vec3d a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3d cross(Vec3d a, Vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3d unit(Vec3d a) { return a * (1.0 / std::sqrt(dot(a, a))); }
Vec3f to_float(Vec3d a) { return {float(a.x), float(a.y), float(a.z)}; }

}  // namespace

AccuracyScene make_accuracy_scene(const AccuracySceneParams& p) {
  AccuracyScene scene;
  scene.mesh = make_spindle(p.segments, p.half_length, p.radius, p.center, p.axis);
  // The ring vertex looked at, its outward direction, and a view 25 degrees around the axis
  // from that normal and slightly from above, so that the rays cross the slivers obliquely.
  const Vec3d target = to_double(scene.mesh.vertices[size_t(2 + p.aimed_vertex % p.segments)]);
  const Vec3d axis = unit(to_double(p.axis));
  const Vec3d radial = unit(target - to_double(p.center));
  const Vec3d tangent = cross(axis, radial);
  const double turn = 25.0 * std::numbers::pi / 180.0;
  const Vec3d view = unit(radial * std::cos(turn) + tangent * std::sin(turn) + axis * 0.05);
  scene.camera.position = to_float(target + view * p.distance);
  scene.camera.look_at = to_float(target);
  scene.camera.up = to_float(axis);
  scene.camera.fov_degrees = p.fov_degrees;
  return scene;
}

std::vector<Ray> camera_rays(const PinholeCamera& camera, int width, int height) {
  const Vec3d z = unit(to_double(camera.look_at) - to_double(camera.position));
  const Vec3d u = unit(cross(to_double(camera.up), z));
  const Vec3d v = cross(z, u);
  const double aspect = double(width) / double(height);
  const double focal = 0.5 / std::tan(camera.fov_degrees * std::numbers::pi / 360.0);
  std::vector<Ray> rays;
  rays.reserve(size_t(width) * size_t(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double px = (x + 0.5) / width, py = (y + 0.5) / height;
      Ray r;
      r.org = camera.position;
      r.dir = to_float(unit(u * ((px - 0.5) * aspect) + v * (0.5 - py) + z * focal));
      rays.push_back(r);
    }
  return rays;
}

std::vector<Ray> rays_through_front(const TriangleMesh& convex_mesh, std::span<const Ray> rays) {
  std::vector<Ray> out;
  out.reserve(rays.size());
  for (Ray r : rays) {
    const auto [t_in, t_out] = convex_interval(convex_mesh, r);
    if (!(t_in > 0.0 && t_out > t_in)) continue;
    r.tnear = 0.0f;
    r.tfar = float(0.5 * (t_in + t_out));
    out.push_back(r);
  }
  return out;
}

std::vector<Ray> accuracy_inside_rays(const AccuracySceneParams& params) {
  const TriangleMesh mesh = make_accuracy_scene(params).mesh;
  const Vec3d axis = unit(to_double(params.axis));
  const float fractions[] = {0.5f, 0.25f, 1.0f / 3.0f, 0.1f};
  std::vector<Ray> rays;
  for (int k = 0; k < 8; ++k) {
    // Off the axis by less than the ring's radius, and along it by up to 1.5.
    const double along = (k / 2 % 2 ? 1.5 : -1.5) + 0.01 * k;
    const Vec3d side{0.1 * (k % 2) - 0.05, 0.0, 0.1 * (k / 4) - 0.05};
    const Vec3f origin = to_float(to_double(params.center) + axis * along + side);
    for (const Ray& r : rays_at_vertices(mesh, origin)) rays.push_back(r);
    for (const Ray& r : rays_at_edges(mesh, origin, fractions)) rays.push_back(r);
  }
  return rays;
}

}  // namespace rtk
