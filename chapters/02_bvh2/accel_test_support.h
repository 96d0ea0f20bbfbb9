/// \file
/// What the tests of chapters 2 and 3 share: the procedural scenes with rays and brute-force
/// answers computed once, and the comparison of a kernel's answers with them. Test code only.
#pragma once

#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "01_base/cpu_features.h"
#include "testing/brute_force.h"
#include "01_base/ray_sets.h"
#include "testing/scenes.h"

namespace rtk::test {

/// A cube of small cubes on an integer grid, each made of 12 axis-aligned triangles, above a
/// floor of two triangles: many faces share planes with each other and with node boxes.
inline TriangleMesh make_box_grid(int n) {
  TriangleMesh mesh;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const uint32_t first = uint32_t(mesh.vertices.size());
        for (int c = 0; c < 8; ++c)
          mesh.vertices.push_back({float(i) + 0.5f * float(c & 1), float(j) + 0.5f * float((c >> 1) & 1),
                                   float(k) + 0.5f * float((c >> 2) & 1)});
        // Two triangles per face of the cube (corner bits: x = 1, y = 2, z = 4).
        const uint32_t faces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                      {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
        for (const auto& f : faces) {
          mesh.triangles.push_back({first + f[0], first + f[1], first + f[2]});
          mesh.triangles.push_back({first + f[0], first + f[2], first + f[3]});
        }
      }
  const uint32_t first = uint32_t(mesh.vertices.size());
  const float e = float(n);
  mesh.vertices.insert(mesh.vertices.end(), {{0, 0, 0}, {e, 0, 0}, {e, 0, e}, {0, 0, e}});
  mesh.triangles.push_back({first, first + 1, first + 2});
  mesh.triangles.push_back({first, first + 2, first + 3});
  return mesh;
}

/// Rays lying in the planes of the mesh's vertices: one direction component is +0 or -0 and
/// the origin's coordinate on that axis is a vertex's, so slab tests meet 0 * inf exactly on
/// node boxes' faces.
inline std::vector<Ray> in_plane_rays(const TriangleMesh& mesh, int count, uint64_t seed) {
  std::mt19937_64 random(seed);
  auto uniform = [&] { return float(double(random() >> 11) * 0x1.0p-53); };
  const Box3f box = mesh.bounds();
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const Vec3f v = mesh.vertices[random() % mesh.vertices.size()];
    const int axis = int(random() % 3);
    Ray r;
    r.org = box.lower - box.size() * 0.25f + Vec3f{uniform(), uniform(), uniform()} * box.size() * 1.5f;
    r.org[axis] = v[axis];
    r.dir = Vec3f{uniform(), uniform(), uniform()} - Vec3f(0.5f);
    r.dir[axis] = (random() & 1) ? 0.0f : -0.0f;
    if (r.dir == Vec3f(0.0f)) r.dir[(axis + 1) % 3] = 1.0f;
    rays.push_back(r);
  }
  return rays;
}

/// Rotates the axes of a point k times: (x, y, z) -> (z, x, y) -> (y, z, x).
inline Vec3f rotate_axes(Vec3f v, int k) {
  for (int i = 0; i < k; ++i) v = {v.z, v.x, v.y};
  return v;
}

/// Three unit squares of two triangles each, square k in a plane normal to axis (k + 2) % 3
/// (square 0 is (0,0,0) (1,0,0) (0,1,0) plus (1,1,0) (0,1,0) (1,0,0)), each moved by (3k,3k,3k),
/// and a seventh triangle far away, so that every tree has an inner node.
inline TriangleMesh make_squares_and_speck() {
  TriangleMesh mesh;
  const Vec3f square[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  for (int k = 0; k < 3; ++k) {
    const uint32_t first = uint32_t(mesh.vertices.size());
    for (const Vec3f& v : square) mesh.vertices.push_back(rotate_axes(v, k) + Vec3f(3.0f * float(k)));
    mesh.triangles.push_back({first, first + 1, first + 2});
    mesh.triangles.push_back({first + 3, first + 2, first + 1});
  }
  const uint32_t first = uint32_t(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), {{20, 20, 20}, {20.5f, 20, 20}, {20, 20.5f, 20}});
  mesh.triangles.push_back({first, first + 1, first + 2});
  return mesh;
}

/// Rays that lie in a face plane of a square triangle's box (the direction component across
/// that plane is +0 or -0) and hit an edge of the triangle lying in that plane at t = 1, for
/// every axis: there the slab test meets 0 * inf = NaN. Möller-Trumbore finds each of these
/// hits exactly (u or v is exactly 0), so a box test that lets the NaN reject the box loses it.
inline std::vector<Ray> face_plane_rays() {
  std::vector<Ray> rays;
  for (int k = 0; k < 3; ++k)
    for (float zero : {0.0f, -0.0f}) {
      const Vec3f orgs[4] = {{0, 0.5f, 1}, {0.5f, 0, 1}, {1, 0.5f, 1}, {0.5f, 1, 1}};
      for (int i = 0; i < 4; ++i) {
        Ray r;
        r.org = rotate_axes(orgs[i], k) + Vec3f(3.0f * float(k));
        r.dir = rotate_axes({i % 2 == 0 ? zero : 0.0f, i % 2 == 1 ? zero : 0.0f, -1.0f}, k);
        rays.push_back(r);
      }
    }
  return rays;
}

/// A scene with its rays and the oracle's answers for them.
struct OracleCase {
  std::string name;
  TriangleMesh mesh;
  std::vector<Ray> rays;
  std::vector<Hit> hits;          ///< brute_force_intersect
  std::vector<uint8_t> occluded;  ///< brute_force_occluded
};

/// The procedural scenes of the traversal tests, each with mixed rays (inside, misses, grazing,
/// zero direction components, invalid), in-plane rays and degenerate triangles; the oracle
/// runs once per test program.
inline const std::vector<OracleCase>& oracle_cases() {
  static const std::vector<OracleCase> cases = [] {
    std::vector<OracleCase> out;
    auto add = [&](std::string name, TriangleMesh mesh, uint64_t seed) {
      add_degenerate_triangles(mesh, 12, seed + 100);
      OracleCase c{std::move(name), std::move(mesh), {}, {}, {}};
      c.rays = mixed_rays(c.mesh.bounds(), 700, seed);
      for (const Ray& r : in_plane_rays(c.mesh, 150, seed + 200)) c.rays.push_back(r);
      for (const Ray& r : c.rays) {
        c.hits.push_back(brute_force_intersect(c.mesh, r));
        c.occluded.push_back(brute_force_occluded(c.mesh, r) ? 1 : 0);
      }
      out.push_back(std::move(c));
    };
    add("random_soup", make_random_soup(500, 11), 1);
    add("sphere", make_sphere(14, 22), 2);
    add("terrain", make_terrain(18, 13), 3);
    add("slivers", make_slivers(250, 14), 4);
    add("box_grid", make_box_grid(3), 5);
    return out;
  }();
  return cases;
}

/// Checks a kernel's closest hits and occlusion against the oracle; reports the first few
/// disagreements in full and counts the rest.
inline void check_against_oracle(const OracleCase& c, const std::vector<Hit>& hits,
                                 const std::vector<uint8_t>& occluded, const std::string& what) {
  int failures = 0;
  for (size_t i = 0; i < c.rays.size(); ++i) {
    const std::string why = compare_hits(c.mesh, c.rays[i], hits[i], c.hits[i]);
    // Occlusion agrees with the oracle, or the oracle's closest hit is a borderline one
    // (compare_hits accepts the kernel's miss there, so it accepts "not occluded" too).
    bool occlusion_ok = occluded[i] == c.occluded[i];
    if (!occlusion_ok && c.occluded[i]) {
      Hit kernel_miss;
      occlusion_ok = compare_hits(c.mesh, c.rays[i], kernel_miss, c.hits[i]).empty();
    }
    if (!occlusion_ok && !c.occluded[i]) {
      // The kernel saw a blocker the oracle did not: acceptable only where its closest hit is
      // itself accepted against the oracle's miss.
      occlusion_ok = hits[i].found() && why.empty();
    }
    if (why.empty() && occlusion_ok) continue;
    if (++failures <= 5) {
      INFO(what << " scene " << c.name << " ray " << i);
      CHECK_MESSAGE(why.empty(), why);
      CHECK_MESSAGE(occlusion_ok, "occluded " << int(occluded[i]) << " oracle " << int(c.occluded[i]));
    }
  }
  INFO(what << " scene " << c.name);
  CHECK(failures == 0);
}

/// Whether two hit arrays are the same bit for bit.
inline bool same_bits(const std::vector<Hit>& a, const std::vector<Hit>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Hit)) == 0;
}

/// The index of the first ray whose hits differ in any bit, or -1.
inline long first_difference(const std::vector<Hit>& a, const std::vector<Hit>& b) {
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
    if (std::memcmp(&a[i], &b[i], sizeof(Hit)) != 0) return long(i);
  return a.size() == b.size() ? -1 : long(std::min(a.size(), b.size()));
}

}  // namespace rtk::test
