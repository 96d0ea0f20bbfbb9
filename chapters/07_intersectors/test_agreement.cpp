// Chapter 7: the intersectors against the double-precision oracle on ordinary rays, and every
// ISA and width against the scalar variant, bit for bit.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "07_intersectors/test_support_ch07.h"
#include "02_bvh2/zero_area.h"
#include "testing/brute_force.h"
#include "01_base/ray_sets.h"
#include "testing/scenes.h"

namespace {

using namespace rtk;

struct NamedMesh {
  std::string name;
  TriangleMesh mesh;
};

std::vector<NamedMesh> ordinary_scenes() {
  std::vector<NamedMesh> scenes;
  scenes.push_back({"sphere", test::make_sphere(12, 24, {0.5f, 0.5f, 0.5f}, 0.4f)});
  scenes.push_back({"soup", test::make_random_soup(300, 71)});
  scenes.push_back({"terrain", test::make_terrain(10, 72)});
  scenes.push_back({"slivers", test::make_slivers(150, 73)});
  test::add_degenerate_triangles(scenes.back().mesh, 20, 74);
  return scenes;
}

}  // namespace

TEST_CASE("ch07: every intersector agrees with the double-precision oracle on ordinary rays") {
  for (const NamedMesh& scene : ordinary_scenes()) {
    const TriangleSoA soa(scene.mesh);
    const std::vector<Ray> rays = test::mixed_rays(scene.mesh.bounds(), 300, 75);
    for (const IntersectorKind kind : kAllIntersectors) {
      CAPTURE(scene.name);
      CAPTURE(intersector_name(kind));
      const std::vector<Hit> hits = test::trace_all(soa, kind, Isa::scalar, 1, rays);
      int found = 0;
      for (size_t i = 0; i < rays.size(); ++i) {
        const Hit oracle = test::brute_force_intersect(scene.mesh, rays[i]);
        CHECK_MESSAGE(test::compare_hits(scene.mesh, rays[i], hits[i], oracle) == "", i);
        found += hits[i].found();
      }
      CHECK(found > int(rays.size()) / 20);  // the rays really meet the geometry
    }
  }
}

TEST_CASE("ch07: every ISA and width finds the scalar variant's hits bit for bit") {
  for (const NamedMesh& scene : ordinary_scenes()) {
    const TriangleSoA soa(scene.mesh);
    const std::vector<Ray> rays = test::mixed_rays(scene.mesh.bounds(), 120, 76);
    for (const IntersectorKind kind : kAllIntersectors) {
      const std::vector<Hit> reference = test::trace_all(soa, kind, Isa::scalar, 1, rays);
      for (const Isa isa : supported_isas())
        for (const int width : kIntersectorWidths) {
          CAPTURE(scene.name);
          CAPTURE(intersector_name(kind));
          CAPTURE(isa_name(isa));
          CAPTURE(width);
          const std::vector<Hit> hits = test::trace_all(soa, kind, isa, width, rays);
          int differ = 0;
          for (size_t i = 0; i < rays.size(); ++i) differ += !test::same_bits(hits[i], reference[i]);
          CHECK(differ == 0);
        }
    }
  }
}

TEST_CASE("ch07: hits lie in [tnear, tfar], and u, v are the weights of p1 and p2") {
  // One triangle, rays aimed at known barycentric points from both sides.
  TriangleMesh mesh;
  mesh.vertices = {{0.25f, -0.5f, 1.0f}, {2.0f, 0.0f, 1.5f}, {0.5f, 1.75f, 0.75f}};
  mesh.triangles = {{0, 1, 2}};
  const TriangleSoA soa(mesh);
  for (const IntersectorKind kind : kAllIntersectors)
    for (const float side : {-1.0f, 1.0f})
      for (const float u : {0.125f, 0.25f, 0.5f})
        for (const float v : {0.125f, 0.25f}) {
          CAPTURE(intersector_name(kind));
          const Vec3f p = mesh.vertices[0] * (1 - u - v) + mesh.vertices[1] * u + mesh.vertices[2] * v;
          Ray ray;
          ray.dir = Vec3f{0.1f, -0.2f, 1.0f} * side;
          ray.org = p - ray.dir * 2.0f;
          std::vector<Ray> rays = {ray, ray, ray};
          rays[1].tfar = 1.99f;  // ends before the triangle
          rays[2].tnear = 2.01f;  // starts after it
          const std::vector<Hit> hits = test::trace_all(soa, kind, Isa::scalar, 1, rays);
          REQUIRE(hits[0].found());
          CHECK(hits[0].t == doctest::Approx(2.0f).epsilon(1e-5));
          CHECK(hits[0].u == doctest::Approx(u).epsilon(1e-4));
          CHECK(hits[0].v == doctest::Approx(v).epsilon(1e-4));
          CHECK(!hits[1].found());
          CHECK(!hits[2].found());
        }
}

TEST_CASE("ch07: rays that are not rays miss and leave the other rays alone") {
  const TriangleMesh mesh = test::make_sphere(8, 16, {0.5f, 0.5f, 0.5f}, 0.4f);
  const TriangleSoA soa(mesh);
  const std::vector<Ray> random = test::random_rays(mesh.bounds(), 40, 77);
  const std::vector<Ray> bad = test::invalid_rays();
  std::vector<Ray> mixed, good;
  for (size_t i = 0; i < random.size() || i < bad.size(); ++i) {
    if (i < random.size()) mixed.push_back(random[i]);
    if (i < bad.size()) mixed.push_back(bad[i]);
  }
  for (const Ray& r : mixed)
    if (is_valid(r)) good.push_back(r);  // (tnear = -inf is a valid ray)
  for (const IntersectorKind kind : kAllIntersectors)
    for (const Isa isa : supported_isas())
      for (const int width : kIntersectorWidths) {
        const std::vector<Hit> alone = test::trace_all(soa, kind, isa, width, good);
        const std::vector<Hit> hits = test::trace_all(soa, kind, isa, width, mixed);
        size_t g = 0;
        for (size_t i = 0; i < mixed.size(); ++i) {
          if (is_valid(mixed[i])) {
            CHECK(test::same_bits(hits[i], alone[g++]));
          } else {
            CHECK(!hits[i].found());
          }
        }
      }
}

TEST_CASE("ch07: zero-area triangles are decided exactly and never hit") {
  // Collinear in exact arithmetic, with steps that are exact in float, near and far from the
  // origin, and repeated vertices.
  TriangleMesh mesh;
  for (const float offset : {0.0f, 1e4f, 1e5f, -4194304.0f}) {
    const Vec3f base = Vec3f{0.75f, -0.5f, 0.25f} * (offset < 0.0f ? 2.0f : 1.0f) + Vec3f(offset);
    const Vec3f step = offset < 0.0f ? Vec3f{1.0f, 0.5f, -2.0f} : Vec3f{0.125f, 0.0625f, -0.25f};
    const uint32_t first = uint32_t(mesh.vertices.size());
    mesh.vertices.push_back(base);
    mesh.vertices.push_back(base + step);
    mesh.vertices.push_back(base + step * 3.0f);
    mesh.vertices.push_back(base + Vec3f{1, 1, 1});
    mesh.triangles.push_back({first, first + 1, first + 2});      // collinear
    mesh.triangles.push_back({first + 2, first, first + 1});      // collinear, rotated
    mesh.triangles.push_back({first, first + 3, first});          // a repeated vertex
    mesh.triangles.push_back({first + 3, first + 3, first + 3});  // a point
    CHECK(is_zero_area(mesh.vertices[first], mesh.vertices[first + 1], mesh.vertices[first + 2]));
    CHECK(is_zero_area(mesh.vertices[first], mesh.vertices[first + 3], mesh.vertices[first]));
  }
  // A sliver that is thin but not flat is not zero-area.
  CHECK(!is_zero_area({0, 0, 0}, {1, 1, 1}, {1, 1, std::nextafter(1.0f, 2.0f)}));
  const TriangleSoA soa(mesh);
  // Rays from many directions through every vertex and every edge midpoint.
  std::vector<Ray> rays;
  for (const Vec3f& p : mesh.vertices)
    for (int k = 0; k < 26; ++k) {
      const Vec3f d{float(k % 3) - 1.0f, float(k / 3 % 3) - 1.0f, float(k / 9 % 3) - 1.0f};
      if (d == Vec3f(0)) continue;
      Ray r;
      r.org = p - d * 0.75f;
      r.dir = d + Vec3f{0.01f * float(k), 0.0f, 0.0f};
      rays.push_back(r);
      r.org = p - d * 0.75f + (p - mesh.vertices[0]) * 0.5f;
      rays.push_back(r);
    }
  for (const IntersectorKind kind : kAllIntersectors)
    for (const Isa isa : supported_isas())
      for (const int width : kIntersectorWidths) {
        CAPTURE(intersector_name(kind));
        CAPTURE(isa_name(isa));
        CAPTURE(width);
        const std::vector<Hit> hits = test::trace_all(soa, kind, isa, width, rays);
        CHECK(std::count_if(hits.begin(), hits.end(), [](const Hit& h) { return h.found(); }) == 0);
      }
}

TEST_CASE("ch07: bad arguments are refused with a message") {
  const TriangleMesh sphere = test::make_sphere(4, 8);
  const TriangleSoA soa(sphere);
  std::vector<Ray> rays(3);
  std::vector<Hit> hits(2);
  CHECK_THROWS_AS(rtk::scalar::intersect_all(soa, IntersectorKind::moeller, 1, rays, hits), std::invalid_argument);
  hits.resize(3);
  CHECK_THROWS_WITH_AS(rtk::scalar::intersect_all(soa, IntersectorKind::moeller, 3, rays, hits),
                       doctest::Contains("width 3"), std::invalid_argument);
  TriangleMesh broken = sphere;
  broken.triangles.push_back({0, 1, uint32_t(broken.vertices.size())});
  CHECK_THROWS_AS(TriangleSoA{broken}, std::invalid_argument);
}
