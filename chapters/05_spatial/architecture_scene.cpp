#include "05_spatial/architecture_scene.h"

#include <array>
#include <cmath>

namespace rtk {

namespace {

/// SplitMix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number generators",
/// OOPSLA 2014): tiny, and the same numbers on every platform, unlike <random>'s distributions.
struct SplitMix {
  uint64_t state;
  uint64_t next() {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  /// A float in [lo, hi).
  float uniform(float lo, float hi) { return lo + (hi - lo) * float(next() >> 40) * 0x1.0p-24f; }
};

void add_quad(TriangleMesh& m, Vec3f a, Vec3f b, Vec3f c, Vec3f d) {
  const uint32_t i = uint32_t(m.vertices.size());
  for (const Vec3f& p : {a, b, c, d}) m.vertices.push_back(p);
  m.triangles.push_back({i, i + 1, i + 2});
  m.triangles.push_back({i, i + 2, i + 3});
}

/// A prism of square section `w` around the segment from `p` to `q`: four long sides and two
/// end caps, 12 triangles.
void add_beam(TriangleMesh& m, Vec3f p, Vec3f q, float w) {
  const Vec3f d = normalize(q - p);
  const Vec3f helper = std::fabs(d.y) < 0.9f ? Vec3f(0, 1, 0) : Vec3f(1, 0, 0);
  const Vec3f u = normalize(cross(d, helper)) * (0.5f * w), v = normalize(cross(d, u)) * (0.5f * w);
  const std::array<Vec3f, 4> ring = {u + v, u - v, (u * -1.0f) - v, (u * -1.0f) + v};
  for (int k = 0; k < 4; ++k) {
    const Vec3f a = ring[size_t(k)], b = ring[size_t((k + 1) % 4)];
    add_quad(m, p + a, q + a, q + b, p + b);
  }
  add_quad(m, p + ring[0], p + ring[1], p + ring[2], p + ring[3]);
  add_quad(m, q + ring[3], q + ring[2], q + ring[1], q + ring[0]);
}

/// An axis-aligned box from `lo` to `hi` (12 triangles).
void add_box(TriangleMesh& m, Vec3f lo, Vec3f hi) {
  add_quad(m, {lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z});
  add_quad(m, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z});
  add_quad(m, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {lo.x, lo.y, hi.z});
  add_quad(m, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z});
  add_quad(m, {lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, lo.y, lo.z});
  add_quad(m, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z});
}

}  // namespace

TriangleMesh make_architecture(int pillars, int beams, int roof_strips, uint64_t seed) {
  TriangleMesh m;
  SplitMix rng{seed};
  const float sx = 10.0f, sy = 4.0f, sz = 10.0f;
  // Floor and four walls.
  add_quad(m, {0, 0, 0}, {0, 0, sz}, {sx, 0, sz}, {sx, 0, 0});
  add_quad(m, {0, 0, 0}, {sx, 0, 0}, {sx, sy, 0}, {0, sy, 0});
  add_quad(m, {0, 0, sz}, {0, sy, sz}, {sx, sy, sz}, {sx, 0, sz});
  add_quad(m, {0, 0, 0}, {0, sy, 0}, {0, sy, sz}, {0, 0, sz});
  add_quad(m, {sx, 0, 0}, {sx, 0, sz}, {sx, sy, sz}, {sx, sy, 0});
  // Pillars on a regular grid.
  for (int i = 0; i < pillars; ++i)
    for (int j = 0; j < pillars; ++j) {
      const float x = (float(i) + 0.5f) * sx / float(pillars), z = (float(j) + 0.5f) * sz / float(pillars);
      add_box(m, {x - 0.15f, 0.0f, z - 0.15f}, {x + 0.15f, sy * 0.8f, z + 0.15f});
    }
  // Diagonal beams from near one wall to near the opposite one.
  for (int b = 0; b < beams; ++b) {
    const bool along_x = (b & 1) == 0;
    const Vec3f p = along_x ? Vec3f(rng.uniform(0.1f, 1.5f), rng.uniform(0.5f, sy), rng.uniform(0.1f, sz - 0.1f))
                            : Vec3f(rng.uniform(0.1f, sx - 0.1f), rng.uniform(0.5f, sy), rng.uniform(0.1f, 1.5f));
    const Vec3f q = along_x ? Vec3f(rng.uniform(sx - 1.5f, sx - 0.1f), rng.uniform(0.5f, sy), rng.uniform(0.1f, sz - 0.1f))
                            : Vec3f(rng.uniform(0.1f, sx - 0.1f), rng.uniform(0.5f, sy), rng.uniform(sz - 1.5f, sz - 0.1f));
    add_beam(m, p, q, rng.uniform(0.03f, 0.1f));
  }
  // The roof: two planes rising from the long walls to a ridge, each cut into thin strips that
  // run down the slope diagonally (rafters).
  for (int s = 0; s < roof_strips; ++s) {
    const float z0 = sz * float(s) / float(roof_strips), z1 = sz * float(s + 1) / float(roof_strips);
    const float skew = 0.5f * sz / float(roof_strips) * 6.0f;
    add_quad(m, {0, sy, z0}, {0, sy, z1}, {0.5f * sx, sy + 2.0f, z1 + skew}, {0.5f * sx, sy + 2.0f, z0 + skew});
    add_quad(m, {sx, sy, z0}, {0.5f * sx, sy + 2.0f, z0 + skew}, {0.5f * sx, sy + 2.0f, z1 + skew}, {sx, sy, z1});
  }
  return m;
}

}  // namespace rtk
