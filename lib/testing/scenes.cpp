#include "testing/scenes.h"

#include <cmath>
#include <numbers>
#include <random>

namespace rtk::test {

namespace {

// A fixed generator and distribution implementation, so scenes are the same everywhere.
struct Random {
  std::mt19937_64 engine;
  explicit Random(uint64_t seed) : engine(seed) {}
  float uniform() { return float(double(engine() >> 11) * 0x1.0p-53); }
  Vec3f point() { float x = uniform(), y = uniform(); return {x, y, uniform()}; }
};

}  // namespace

TriangleMesh make_sphere(int rings, int segments, Vec3f center, float radius) {
  TriangleMesh mesh;
  const float pi = std::numbers::pi_v<float>;
  mesh.vertices.push_back(center + Vec3f{0, radius, 0});  // north pole
  for (int r = 1; r < rings; ++r) {
    const float theta = pi * float(r) / float(rings);
    for (int s = 0; s < segments; ++s) {
      const float phi = 2 * pi * float(s) / float(segments);
      mesh.vertices.push_back(center + radius * Vec3f{std::sin(theta) * std::cos(phi),
                                                      std::cos(theta),
                                                      std::sin(theta) * std::sin(phi)});
    }
  }
  mesh.vertices.push_back(center + Vec3f{0, -radius, 0});  // south pole
  const uint32_t south = uint32_t(mesh.vertices.size() - 1);
  auto ring_vertex = [&](int r, int s) { return uint32_t(1 + (r - 1) * segments + (s % segments)); };
  for (int s = 0; s < segments; ++s) mesh.triangles.push_back({0, ring_vertex(1, s + 1), ring_vertex(1, s)});
  for (int r = 1; r + 1 < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const uint32_t a = ring_vertex(r, s), b = ring_vertex(r, s + 1);
      const uint32_t c = ring_vertex(r + 1, s), d = ring_vertex(r + 1, s + 1);
      mesh.triangles.push_back({a, b, d});
      mesh.triangles.push_back({a, d, c});
    }
  }
  for (int s = 0; s < segments; ++s)
    mesh.triangles.push_back({ring_vertex(rings - 1, s), ring_vertex(rings - 1, s + 1), south});
  return mesh;
}

TriangleMesh make_random_soup(int count, uint64_t seed, float max_size) {
  Random random(seed);
  TriangleMesh mesh;
  for (int i = 0; i < count; ++i) {
    const Vec3f base = random.point();
    const uint32_t first = uint32_t(mesh.vertices.size());
    mesh.vertices.push_back(base);
    for (int k = 0; k < 2; ++k) mesh.vertices.push_back(base + (random.point() - Vec3f(0.5f)) * max_size);
    mesh.triangles.push_back({first, first + 1, first + 2});
  }
  return mesh;
}

TriangleMesh make_terrain(int n, uint64_t seed) {
  Random random(seed);
  TriangleMesh mesh;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float x = float(i) / float(n), z = float(j) / float(n);
      const float height = 0.1f * std::sin(6.0f * x) * std::cos(5.0f * z) + 0.01f * random.uniform();
      mesh.vertices.push_back({x, height, z});
    }
  auto index = [n](int i, int j) { return uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      mesh.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  return mesh;
}

TriangleMesh make_slivers(int count, uint64_t seed) {
  Random random(seed);
  TriangleMesh mesh;
  for (int i = 0; i < count; ++i) {
    // From near one corner region to near the opposite one, with a tiny width.
    const Vec3f a = random.point() * 0.2f;
    const Vec3f b = Vec3f(0.8f) + random.point() * 0.2f;
    const Vec3f width = (random.point() - Vec3f(0.5f)) * 0.01f;
    const uint32_t first = uint32_t(mesh.vertices.size());
    mesh.vertices.push_back(a);
    mesh.vertices.push_back(b);
    mesh.vertices.push_back(b + width);
    mesh.triangles.push_back({first, first + 1, first + 2});
  }
  return mesh;
}

void add_degenerate_triangles(TriangleMesh& mesh, int count, uint64_t seed) {
  Random random(seed);
  for (int i = 0; i < count; ++i) {
    const Vec3f a = random.point(), b = random.point();
    const uint32_t first = uint32_t(mesh.vertices.size());
    mesh.vertices.push_back(a);
    mesh.vertices.push_back(b);
    mesh.vertices.push_back(i % 2 ? a : (a + b) * 0.5f);  // a repeated vertex, or collinear
    mesh.triangles.push_back({first, first + 1, first + 2});
  }
}

}  // namespace rtk::test
