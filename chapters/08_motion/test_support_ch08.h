/// \file
/// What chapter 8's tests share: moving scenes, rays with shutter times, and the oracle at the
/// ray's time. Test code only.
#pragma once

#include <doctest/doctest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "08_motion/motion_mesh.h"
#include "testing/brute_force.h"
#include "01_base/ray_sets.h"
#include "testing/scenes.h"

namespace rtk::test {

/// Appends `other` to `mesh`, shifting its indices.
inline void append_mesh(TriangleMesh& mesh, const TriangleMesh& other) {
  const uint32_t first = uint32_t(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (auto t : other.triangles) mesh.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
}

/// A moving scene and its mesh at time 1: a sphere that flies across by `shift` (a fraction of
/// the unit scene), a soup of which about a third of the vertices jitter by up to `shift`, a
/// static wall behind them, and zero-area triangles.
struct MovingScene {
  TriangleMesh t0, t1;
};
inline MovingScene make_moving_scene(float shift, uint64_t seed) {
  MovingScene s;
  append_mesh(s.t0, make_sphere(8, 14, {0.3f, 0.5f, 0.5f}, 0.2f));
  const size_t sphere_vertices = s.t0.vertices.size();
  append_mesh(s.t0, make_random_soup(160, seed, 0.2f));
  const size_t soup_vertices = s.t0.vertices.size();
  s.t0.vertices.insert(s.t0.vertices.end(), {{-0.2f, -0.2f, 1.2f}, {1.2f, -0.2f, 1.2f}, {1.2f, 1.2f, 1.2f}, {-0.2f, 1.2f, 1.2f}});
  const uint32_t w = uint32_t(soup_vertices);
  s.t0.triangles.push_back({w, w + 1, w + 2});
  s.t0.triangles.push_back({w, w + 2, w + 3});
  add_degenerate_triangles(s.t0, 3, seed + 1);
  s.t1 = s.t0;
  std::mt19937_64 random(seed + 2);
  auto uniform = [&] { return float(double(random() >> 11) * 0x1.0p-53); };
  for (size_t v = 0; v < sphere_vertices; ++v) s.t1.vertices[v] += Vec3f{shift, 0.3f * shift, 0.0f};
  for (size_t v = sphere_vertices; v < soup_vertices; ++v)
    if (random() % 3 == 0) s.t1.vertices[v] += (Vec3f{uniform(), uniform(), uniform()} - Vec3f(0.5f)) * (2.0f * shift);
  return s;
}

/// Rays through the scene's box at both ends of the shutter (mixed_rays: random, axis-aligned,
/// grazing and invalid ones), with times: exactly 0 for every fifth, exactly 1 for the next,
/// uniform in [0, 1] for the rest.
inline std::vector<Ray> timed_rays(const MotionMesh& mesh, int count, uint64_t seed) {
  const Box3f box = merge(mesh.at(0.0f).bounds(), mesh.at(1.0f).bounds());
  std::vector<Ray> rays = mixed_rays(box, count, seed);
  std::mt19937_64 random(seed + 7);
  for (size_t i = 0; i < rays.size(); ++i)
    rays[i].time = i % 5 == 0 ? 0.0f : i % 5 == 1 ? 1.0f : float(double(random() >> 40) * 0x1.0p-24);
  return rays;
}

/// The oracle: brute force over the triangles interpolated at the ray's time.
inline Hit oracle_at_time(const MotionMesh& mesh, const Ray& ray) {
  if (!is_valid_motion_ray(ray)) return Hit{};
  return brute_force_intersect(mesh.at(ray.time), ray);
}

}  // namespace rtk::test
