// Ray generation: the same seed gives the same bytes, and each kind of ray has the properties
// lib/replay/ray_generator.h documents.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "io/replay_files.h"
#include "replay/ray_generator.h"
#include "testing/scenes.h"

namespace {

using rtk::RayKind;
using rtk::Vec3f;

constexpr RayKind kKinds[] = {RayKind::primary, RayKind::diffuse, RayKind::shadow, RayKind::random};

// FNV-1a over bytes: pins the generator's output so that a change to it is noticed (replay
// files made yesterday must still mean the same rays).
uint64_t fnv1a(const std::string& bytes) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

// The triangle whose plane and interior hold p (within a tolerance), or -1.
int triangle_under(const rtk::TriangleMesh& mesh, Vec3f p, float tolerance) {
  for (uint32_t prim = 0; prim < mesh.size(); ++prim) {
    const Vec3f a = mesh.vertex(prim, 0), b = mesh.vertex(prim, 1), c = mesh.vertex(prim, 2);
    const Vec3f n = cross(b - a, c - a);
    const float area2 = length(n);
    if (area2 == 0) continue;
    if (std::fabs(dot(p - a, n)) / area2 > tolerance) continue;
    // Barycentric weights from sub-triangle areas, signed by the normal.
    const float wa = dot(cross(b - p, c - p), n) / (area2 * area2);
    const float wb = dot(cross(c - p, a - p), n) / (area2 * area2);
    const float wc = 1 - wa - wb;
    const float e = 1e-4f;
    if (wa >= -e && wb >= -e && wc >= -e) return int(prim);
  }
  return -1;
}

Vec3f unit_normal(const rtk::TriangleMesh& mesh, uint32_t prim) {
  return normalize(cross(mesh.vertex(prim, 1) - mesh.vertex(prim, 0), mesh.vertex(prim, 2) - mesh.vertex(prim, 0)));
}

}  // namespace

TEST_CASE("io: rays are deterministic for a seed, and pinned") {
  const rtk::TriangleMesh mesh = rtk::test::make_sphere(6, 12);
  for (RayKind kind : kKinds) {
    CAPTURE(rtk::ray_kind_name(kind));
    const std::string a = rtk::format_rays(rtk::generate_rays(mesh, kind, 257, 5));
    const std::string b = rtk::format_rays(rtk::generate_rays(mesh, kind, 257, 5));
    const std::string c = rtk::format_rays(rtk::generate_rays(mesh, kind, 257, 6));
    CHECK(a == b);
    CHECK(a != c);
  }
  // The bits of one file per kind: these hashes change only when the generator does. The
  // scene is made with basic arithmetic only (no sin or cos), so its bits are the same
  // everywhere too.
  const rtk::TriangleMesh soup = rtk::test::make_random_soup(60, 1);
  CHECK(fnv1a(rtk::format_rays(rtk::generate_rays(soup, RayKind::primary, 100, 1))) == 17543926784362689471ull);
  CHECK(fnv1a(rtk::format_rays(rtk::generate_rays(soup, RayKind::diffuse, 100, 1))) == 8534173803961296716ull);
  CHECK(fnv1a(rtk::format_rays(rtk::generate_rays(soup, RayKind::shadow, 100, 1))) == 15033913556774111415ull);
  CHECK(fnv1a(rtk::format_rays(rtk::generate_rays(soup, RayKind::random, 100, 1))) == 4562346853830495388ull);
}

TEST_CASE("io: kind names parse") {
  for (RayKind kind : kKinds) CHECK(rtk::parse_ray_kind(rtk::ray_kind_name(kind)) == kind);
  CHECK(!rtk::parse_ray_kind("Primary"));
}

TEST_CASE("io: primary rays leave one camera outside the scene, normalized, and mostly hit") {
  const rtk::TriangleMesh mesh = rtk::test::make_sphere(8, 16, {3, -2, 1}, 2.0f);
  const rtk::Box3f box = rtk::used_bounds(mesh);
  for (size_t n : {size_t(1), size_t(2), size_t(1000)}) {
    const auto rays = rtk::generate_rays(mesh, RayKind::primary, n, 3);
    REQUIRE(rays.size() == n);
    for (const rtk::Ray& r : rays) {
      CHECK(r.org == rtk::primary_camera_position(box));
      CHECK(std::fabs(length(r.dir) - 1.0f) < 1e-5f);
      CHECK(r.tnear == 0.0f);
      CHECK(std::isinf(r.tfar));
      CHECK(r.time >= 0.0f);
      CHECK(r.time < 1.0f);
    }
  }
  CHECK(!box.contains(rtk::primary_camera_position(box)));
  // The sphere around the box fills 90% of the square image's height: a disc of radius 0.9
  // in a 2 x 2 square, so pi 0.81 / 4 = 64% of the rays point into it.
  const auto rays = rtk::generate_rays(mesh, RayKind::primary, 4096, 3);
  const float radius = 0.5f * length(box.size());
  int toward = 0;
  for (const rtk::Ray& r : rays) {
    const Vec3f to_center = box.center() - r.org;
    const float sin_angle = length(cross(r.dir, normalize(to_center)));
    toward += sin_angle < radius / length(to_center);
  }
  CHECK(double(toward) / 4096 == doctest::Approx(0.636).epsilon(0.04));
}

TEST_CASE("io: diffuse rays start on surfaces, cosine-distributed on both sides") {
  const rtk::TriangleMesh mesh = rtk::test::make_sphere(6, 10);
  const rtk::Box3f box = rtk::used_bounds(mesh);
  const auto rays = rtk::generate_rays(mesh, RayKind::diffuse, 2000, 11);
  double sum_cos = 0;
  int front = 0;
  for (const rtk::Ray& r : rays) {
    const int prim = triangle_under(mesh, r.org, 1e-5f);
    REQUIRE(prim >= 0);
    CHECK(std::fabs(length(r.dir) - 1.0f) < 1e-5f);
    CHECK(r.tnear == doctest::Approx(rtk::surface_epsilon(box)));
    CHECK(r.tnear > 0.0f);
    CHECK(std::isinf(r.tfar));
    const float c = dot(r.dir, unit_normal(mesh, uint32_t(prim)));
    sum_cos += std::fabs(c);
    front += c > 0;
  }
  // For a cosine distribution the mean cosine is 2/3; the side is a fair coin.
  CHECK(sum_cos / 2000 == doctest::Approx(2.0 / 3.0).epsilon(0.03));
  CHECK(front > 900);
  CHECK(front < 1100);
}

TEST_CASE("io: surface points are chosen by area, never on zero-area triangles") {
  rtk::TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {3, 0, 1}, {0, 2, 1}, {5, 5, 5}};
  mesh.triangles = {{0, 1, 2}, {6, 6, 6}, {3, 4, 5}};  // areas 0.5, 0, 3
  const auto rays = rtk::generate_rays(mesh, RayKind::diffuse, 4000, 2);
  int big = 0;
  for (const rtk::Ray& r : rays) {
    const int prim = triangle_under(mesh, r.org, 1e-5f);
    REQUIRE(prim >= 0);
    CHECK(prim != 1);
    big += prim == 2;
  }
  CHECK(double(big) / 4000 == doctest::Approx(3.0 / 3.5).epsilon(0.03));
}

TEST_CASE("io: shadow rays run from a surface to just short of the light") {
  const rtk::TriangleMesh mesh = rtk::test::make_terrain(6, 4);
  const rtk::Box3f box = rtk::used_bounds(mesh);
  const Vec3f light = rtk::shadow_light_position(box);
  CHECK(light.y > box.upper.y);
  const auto rays = rtk::generate_rays(mesh, RayKind::shadow, 500, 9);
  for (const rtk::Ray& r : rays) {
    CHECK(triangle_under(mesh, r.org, 1e-5f) >= 0);
    const Vec3f end = r.org + r.dir;  // t = 1 is the light
    CHECK(length(end - light) < 1e-5f * length(box.size()));
    CHECK(r.tnear > 0.0f);
    CHECK(r.tfar < 1.0f);
    CHECK(r.tnear * length(r.dir) == doctest::Approx(rtk::surface_epsilon(box)).epsilon(1e-3));
    CHECK((1.0f - r.tfar) * length(r.dir) == doctest::Approx(rtk::surface_epsilon(box)).epsilon(1e-2));
  }
}

TEST_CASE("io: random rays start in and around the box, normalized") {
  const rtk::TriangleMesh mesh = rtk::test::make_random_soup(50, 3);
  const rtk::Box3f box = rtk::used_bounds(mesh);
  const auto rays = rtk::generate_rays(mesh, RayKind::random, 2000, 4);
  int inside = 0;
  const Vec3f margin = box.size() * 0.5f + Vec3f(0.05f * length(box.size()));
  const rtk::Box3f outer{box.lower - margin, box.upper + margin};
  for (const rtk::Ray& r : rays) {
    CHECK(outer.contains(r.org));
    CHECK(std::fabs(length(r.dir) - 1.0f) < 1e-5f);
    inside += box.contains(r.org);
  }
  CHECK(inside > 100);
  CHECK(inside < 1900);
}

TEST_CASE("io: scenes rays cannot be made for are refused") {
  rtk::TriangleMesh empty;
  CHECK_THROWS_AS(rtk::generate_rays(empty, RayKind::primary, 10, 1), std::invalid_argument);
  rtk::TriangleMesh flat;
  flat.vertices = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  flat.triangles = {{0, 1, 2}};
  CHECK_THROWS_AS(rtk::generate_rays(flat, RayKind::diffuse, 10, 1), std::invalid_argument);
  CHECK_THROWS_AS(rtk::generate_rays(flat, RayKind::shadow, 10, 1), std::invalid_argument);
  CHECK(rtk::generate_rays(flat, RayKind::random, 10, 1).size() == 10);
}
