#include "07_intersectors/stability_meshes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <tuple>

namespace rtk {

namespace {

struct Vec3d {
  double x, y, z;
};
Vec3d to_double(Vec3f v) { return {v.x, v.y, v.z}; }
Vec3d sub(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3d cross(Vec3d a, Vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3d unit(Vec3d a) {
  const double s = 1.0 / std::sqrt(dot(a, a));
  return {a.x * s, a.y * s, a.z * s};
}

// Two unit vectors that complete `n` to an orthonormal basis.
void basis(Vec3d n, Vec3d& e1, Vec3d& e2) {
  const Vec3d helper = std::fabs(n.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  e1 = unit(cross(helper, n));
  e2 = cross(n, e1);
}

Vec3f point(Vec3d c, double r, Vec3d e1, Vec3d e2, double angle) {
  const double cs = std::cos(angle), sn = std::sin(angle);
  return {float(c.x + r * (cs * e1.x + sn * e2.x)), float(c.y + r * (cs * e1.y + sn * e2.y)),
          float(c.z + r * (cs * e1.z + sn * e2.z))};
}

}  // namespace

TriangleMesh make_tiled_box(int n, const Box3f& box) {
  TriangleMesh mesh;
  std::map<std::tuple<int, int, int>, uint32_t> index;
  auto coordinate = [&](int axis, int i) {
    if (i == 0) return box.lower[axis];
    if (i == n) return box.upper[axis];
    return box.lower[axis] + (box.upper[axis] - box.lower[axis]) * (float(i) / float(n));
  };
  auto vertex = [&](int i, int j, int k) {
    const auto [it, inserted] = index.try_emplace({i, j, k}, uint32_t(mesh.vertices.size()));
    if (inserted) mesh.vertices.push_back({coordinate(0, i), coordinate(1, j), coordinate(2, k)});
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      auto at = [&](int u, int v) {
        int g[3];
        g[axis] = side * n;
        g[b] = u;
        g[c] = v;
        return vertex(g[0], g[1], g[2]);
      };
      for (int u = 0; u < n; ++u)
        for (int v = 0; v < n; ++v) {
          const uint32_t p00 = at(u, v), p10 = at(u + 1, v), p11 = at(u + 1, v + 1), p01 = at(u, v + 1);
          // (b, c, axis) is right-handed, so (u, v) counter-clockwise faces +axis: the upper
          // side keeps that winding and the lower side reverses it.
          if (side == 1) {
            mesh.triangles.push_back({p00, p10, p11});
            mesh.triangles.push_back({p00, p11, p01});
          } else {
            mesh.triangles.push_back({p00, p11, p10});
            mesh.triangles.push_back({p00, p01, p11});
          }
        }
    }
  }
  return mesh;
}

TriangleMesh make_spindle(int segments, float half_length, float radius, Vec3f center, Vec3f axis) {
  TriangleMesh mesh;
  const Vec3d a = unit(to_double(axis)), c = to_double(center);
  Vec3d e1, e2;
  basis(a, e1, e2);
  mesh.vertices.push_back({float(c.x + half_length * a.x), float(c.y + half_length * a.y), float(c.z + half_length * a.z)});
  mesh.vertices.push_back({float(c.x - half_length * a.x), float(c.y - half_length * a.y), float(c.z - half_length * a.z)});
  for (int i = 0; i < segments; ++i)
    mesh.vertices.push_back(point(c, radius, e1, e2, 2.0 * std::numbers::pi * i / segments));
  // The ring runs counter-clockwise around +axis (e1 x e2 = a), so (top, r_i, r_i+1) faces out.
  for (int i = 0; i < segments; ++i) {
    const uint32_t r0 = uint32_t(2 + i), r1 = uint32_t(2 + (i + 1) % segments);
    mesh.triangles.push_back({0, r0, r1});
    mesh.triangles.push_back({1, r1, r0});
  }
  return mesh;
}

TriangleMesh make_sliver_fan(int segments, Vec3f center, float radius, Vec3f normal) {
  TriangleMesh mesh;
  const Vec3d n = unit(to_double(normal)), c = to_double(center);
  Vec3d e1, e2;
  basis(n, e1, e2);
  // Angular widths in a geometric progression whose widest is 1000 times its thinnest.
  std::vector<double> widths(static_cast<size_t>(segments));
  double sum = 0;
  for (int i = 0; i < segments; ++i) sum += widths[size_t(i)] = std::pow(1000.0, -double(i) / (segments - 1));
  mesh.vertices.push_back(center);
  double angle = 0;
  for (int i = 0; i < segments; ++i) {
    mesh.vertices.push_back(point(c, radius, e1, e2, angle));
    angle += 2.0 * std::numbers::pi * widths[size_t(i)] / sum;
  }
  // The center is each triangle's last vertex: tests that work from the first vertex (Möller's
  // v0) then measure from the rim, far from where the fan's triangles meet.
  for (int i = 0; i < segments; ++i)
    mesh.triangles.push_back({uint32_t(1 + i), uint32_t(1 + (i + 1) % segments), 0});
  return mesh;
}

TriangleMesh translated(const TriangleMesh& mesh, Vec3f offset) {
  TriangleMesh moved = mesh;
  for (Vec3f& v : moved.vertices) v = v + offset;
  return moved;
}

std::vector<std::array<uint32_t, 2>> unique_edges(const TriangleMesh& mesh) {
  std::vector<std::array<uint32_t, 2>> edges;
  for (const auto& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = tri[size_t(k)], b = tri[size_t((k + 1) % 3)];
      if (a != b) edges.push_back({std::min(a, b), std::max(a, b)});
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

std::vector<Ray> rays_at_vertices(const TriangleMesh& mesh, Vec3f origin) {
  std::vector<Ray> rays;
  for (const Vec3f& v : mesh.vertices) {
    Ray r;
    r.org = origin;
    r.dir = v - origin;
    rays.push_back(r);
  }
  return rays;
}

std::vector<Ray> rays_at_edges(const TriangleMesh& mesh, Vec3f origin, std::span<const float> fractions) {
  std::vector<Ray> rays;
  for (const auto& [ia, ib] : unique_edges(mesh))
    for (const float s : fractions) {
      const Vec3f a = mesh.vertices[ia], b = mesh.vertices[ib];
      Ray r;
      r.org = origin;
      r.dir = (a * (1.0f - s) + b * s) - origin;
      rays.push_back(r);
    }
  return rays;
}

size_t count_misses(std::span<const Hit> hits) {
  return size_t(std::count_if(hits.begin(), hits.end(), [](const Hit& h) { return !h.found(); }));
}

std::array<double, 2> convex_interval(const TriangleMesh& mesh, const Ray& ray) {
  Vec3d inside{0, 0, 0};
  for (const Vec3f& v : mesh.vertices) inside = {inside.x + v.x, inside.y + v.y, inside.z + v.z};
  const double k = 1.0 / double(mesh.vertices.size());
  inside = {inside.x * k, inside.y * k, inside.z * k};
  const Vec3d org = to_double(ray.org), dir = to_double(ray.dir);
  double t_in = -std::numeric_limits<double>::infinity(), t_out = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < mesh.size(); ++i) {
    const Vec3d p0 = to_double(mesh.vertex(uint32_t(i), 0));
    Vec3d n = cross(sub(to_double(mesh.vertex(uint32_t(i), 1)), p0), sub(to_double(mesh.vertex(uint32_t(i), 2)), p0));
    if (dot(n, n) == 0.0) continue;
    if (dot(n, sub(p0, inside)) < 0.0) n = {-n.x, -n.y, -n.z};
    // Inside this face's half-space where n . (x - p0) <= 0, x = org + t dir.
    const double num = dot(n, sub(p0, org)), den = dot(n, dir);
    if (den == 0.0) {
      if (num < 0.0) return {1.0, 0.0};
    } else if (den < 0.0) {
      t_in = std::max(t_in, num / den);
    } else {
      t_out = std::min(t_out, num / den);
    }
  }
  return {t_in, t_out};
}

}  // namespace rtk
