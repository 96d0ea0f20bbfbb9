// Chapter 2: BVH2 traversal against the brute-force oracle, and every ISA against scalar.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "02_bvh2/accel_test_support.h"
#include "02_bvh2/bvh2.h"
#include "02_bvh2/median_builder.h"

using namespace rtk;

namespace {

BVH2 build(const TriangleMesh& mesh, int max_leaf = 4) {
  return make_bvh2(build_median<2>(make_prim_refs(mesh), max_leaf), mesh);
}

std::vector<Hit> trace(Isa isa, const BVH2& bvh, const std::vector<Ray>& rays) {
  std::vector<Hit> hits(rays.size());
  intersect(isa, bvh, rays, hits);
  return hits;
}

std::vector<uint8_t> trace_occlusion(Isa isa, const BVH2& bvh, const std::vector<Ray>& rays) {
  std::vector<uint8_t> occ(rays.size(), 7);
  occluded(isa, bvh, rays, occ);
  return occ;
}

TriangleMesh one_triangle() {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 4, 0}};
  mesh.triangles = {{0, 1, 2}};
  return mesh;
}

}  // namespace

TEST_CASE("ch02: a BVH2 agrees with brute force on every scene, ISA and leaf size") {
  for (const test::OracleCase& c : test::oracle_cases()) {
    for (int max_leaf : {1, 4, 15}) {
      const BVH2 bvh = build(c.mesh, max_leaf);
      for (Isa isa : supported_isas()) {
        const std::string what = "bvh2/" + std::string(isa_name(isa)) + "/leaf" + std::to_string(max_leaf);
        test::check_against_oracle(c, trace(isa, bvh, c.rays), trace_occlusion(isa, bvh, c.rays), what);
      }
    }
  }
}

TEST_CASE("ch02: every ISA's BVH2 kernels give the scalar kernels' answers bit for bit") {
  for (const test::OracleCase& c : test::oracle_cases()) {
    const BVH2 bvh = build(c.mesh);
    const std::vector<Hit> reference = trace(Isa::scalar, bvh, c.rays);
    const std::vector<uint8_t> reference_occ = trace_occlusion(Isa::scalar, bvh, c.rays);
    for (Isa isa : supported_isas()) {
      INFO(isa_name(isa) << " on " << c.name);
      CHECK(test::first_difference(trace(isa, bvh, c.rays), reference) == -1);
      CHECK(trace_occlusion(isa, bvh, c.rays) == reference_occ);
    }
  }
}

TEST_CASE("ch02: invalid rays miss and leave the other rays alone") {
  const test::OracleCase& c = test::oracle_cases()[1];  // the sphere: most valid rays hit it
  const BVH2 bvh = build(c.mesh);
  const std::vector<Ray> valid = test::random_rays(c.mesh.bounds(), 200, 77);
  std::vector<Ray> invalid;  // invalid_rays() also holds a valid one: tnear = -inf
  for (const Ray& r : test::invalid_rays())
    if (!is_valid(r)) invalid.push_back(r);
  REQUIRE(invalid.size() > 10);
  // Interleave: every other ray is invalid.
  std::vector<Ray> mixed;
  for (size_t i = 0; i < valid.size(); ++i) {
    mixed.push_back(valid[i]);
    mixed.push_back(invalid[i % invalid.size()]);
  }
  for (Isa isa : supported_isas()) {
    INFO(isa_name(isa));
    const std::vector<Hit> alone = trace(isa, bvh, valid);
    const std::vector<Hit> together = trace(isa, bvh, mixed);
    const std::vector<uint8_t> occ_alone = trace_occlusion(isa, bvh, valid);
    const std::vector<uint8_t> occ_together = trace_occlusion(isa, bvh, mixed);
    int hits = 0;
    for (size_t i = 0; i < valid.size(); ++i) {
      CHECK(test::first_difference({alone[i]}, {together[2 * i]}) == -1);
      CHECK(occ_alone[i] == occ_together[2 * i]);
      CHECK_FALSE(together[2 * i + 1].found());
      CHECK(occ_together[2 * i + 1] == 0);
      hits += alone[i].found();
    }
    CHECK(hits > 100);  // the valid rays do hit things, so "leave alone" is tested
  }
}

TEST_CASE("ch02: Möller-Trumbore through a BVH2: analytic hits, both sides, closed interval") {
  const TriangleMesh mesh = one_triangle();
  const BVH2 bvh = build(mesh);
  CHECK(is_leaf(bvh.root));  // one triangle: the root is a leaf
  Ray down;
  down.org = {0.5f, 1.0f, 3.0f};
  down.dir = {0, 0, -2};
  Ray up = down;
  up.org.z = -3.0f;
  up.dir.z = 2.0f;
  Ray at_tnear = down, at_tfar = down, short_ray = down;
  at_tnear.tnear = 1.5f;  // the hit is at t = 1.5 exactly
  at_tfar.tfar = 1.5f;
  short_ray.tfar = 1.4999f;
  const std::vector<Ray> rays = {down, up, at_tnear, at_tfar, short_ray};
  for (Isa isa : supported_isas()) {
    INFO(isa_name(isa));
    const std::vector<Hit> hits = trace(isa, bvh, rays);
    for (int i = 0; i < 4; ++i) {
      CHECK(hits[size_t(i)].prim == 0);
      CHECK(hits[size_t(i)].t == 1.5f);
      CHECK(hits[size_t(i)].u == doctest::Approx(0.25));  // weight of p1 = (2, 0, 0)
      CHECK(hits[size_t(i)].v == doctest::Approx(0.25));  // weight of p2 = (0, 4, 0)
    }
    CHECK_FALSE(hits[4].found());
    CHECK(trace_occlusion(isa, bvh, rays) == std::vector<uint8_t>{1, 1, 1, 1, 0});
  }
}

// The closed interval at every scale: a ray that ends exactly at its hit, or starts there,
// finds it, and one float shorter does not, by closest hit and by occlusion alike. Shared edges
// need the first (the closest-hit rule compares hits at equal t), and any shortcut that decides
// the distance before the division must keep both. Triangles from 1e-12 to 1e12 across and
// directions from 1e-6 to 1e6 long put t |det| between about 1e-36 and 1e36, near both ends of
// the float range (smaller triangles underflow the distance to 0).
TEST_CASE("ch02: Möller-Trumbore finds a hit at either end of the ray, at every scale") {
  std::mt19937_64 random(2024);
  auto uniform = [&] { return float(double(random() >> 11) * 0x1.0p-53); };
  int cases = 0;
  for (float scale : {1e-12f, 1e-6f, 1.0f, 1e6f, 1e12f}) {
    for (float length : {1e-6f, 1.0f, 1e6f}) {
      for (int i = 0; i < 40; ++i) {
        TriangleMesh mesh;
        for (int k = 0; k < 3; ++k)
          mesh.vertices.push_back(Vec3f{uniform(), uniform(), uniform()} * (2.0f * scale) -
                                  Vec3f(scale));
        mesh.triangles = {{0, 1, 2}};
        const BVH2 bvh = build(mesh);
        // A ray from a random point near the triangle towards a point inside it.
        const float b1 = uniform() * 0.5f, b2 = uniform() * 0.5f;
        const Vec3f target =
            mesh.vertices[0] * (1.0f - b1 - b2) + mesh.vertices[1] * b1 + mesh.vertices[2] * b2;
        Ray ray;
        ray.org = target + (Vec3f{uniform(), uniform(), uniform()} - Vec3f(0.5f)) * (8.0f * scale);
        ray.dir = (target - ray.org) * (length / scale);
        const Hit full = trace(Isa::scalar, bvh, {ray})[0];
        if (!full.found()) continue;  // the target rounded off an edge, or the triangle is a sliver
        ++cases;
        Ray ends_at = ray, starts_at = ray, ends_before = ray, starts_after = ray;
        ends_at.tfar = full.t;
        starts_at.tnear = full.t;
        ends_before.tfar = std::nextafter(full.t, 0.0f);
        starts_after.tnear = std::nextafter(full.t, std::numeric_limits<float>::infinity());
        const std::vector<Ray> rays = {ends_at, starts_at, ends_before, starts_after};
        for (Isa isa : supported_isas()) {
          INFO(isa_name(isa) << ", scale " << scale << ", length " << length << ", case " << i);
          const std::vector<Hit> hits = trace(isa, bvh, rays);
          CHECK(hits[0].t == full.t);
          CHECK(hits[1].t == full.t);
          CHECK_FALSE(hits[2].found());
          CHECK_FALSE(hits[3].found());
          CHECK(trace_occlusion(isa, bvh, rays) == std::vector<uint8_t>{1, 1, 0, 0});
        }
      }
    }
  }
  CHECK(cases > 400);  // most of the 600 rays hit
}

// [ch02-test-face-plane]
TEST_CASE("ch02: a ray lying in a face plane of a box still finds the edge it hits there") {
  const TriangleMesh mesh = test::make_squares_and_speck();
  const BVH2 bvh = build(mesh, 1);
  REQUIRE_FALSE(is_leaf(bvh.root));
  const std::vector<Ray> rays = test::face_plane_rays();
  for (Isa isa : supported_isas()) {
    const std::vector<Hit> hits = trace(isa, bvh, rays);
    for (size_t i = 0; i < rays.size(); ++i) {
      INFO(isa_name(isa) << " ray " << i);
      CHECK(hits[i].prim <= 5);
      CHECK(hits[i].t == 1.0f);
      CHECK((hits[i].u == 0.0f || hits[i].v == 0.0f));
    }
    CHECK(trace_occlusion(isa, bvh, rays) == std::vector<uint8_t>(rays.size(), 1));
  }
}
// [ch02-test-face-plane]

TEST_CASE("ch02: zero-area triangles are never hit") {
  // Collinear float vertices whose float edges are not exactly parallel, and a repeated vertex.
  TriangleMesh mesh;
  mesh.vertices = {{0.1f, 0.2f, 0.3f}, {0.7f, 0.9f, 1.3f}, {0.4f, 0.55f, 0.8f}, {1, 1, 1}, {2, 0, 1}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 3}};
  const BVH2 bvh = build(mesh);
  std::vector<Ray> rays = test::random_rays(mesh.bounds(), 2000, 5);
  for (int i = 0; i < 200; ++i) {  // rays aimed right at the segments
    Ray r;
    const float s = float(i) / 200.0f;
    r.org = Vec3f{0.1f, 0.2f, 0.3f} + s * Vec3f{0.6f, 0.7f, 1.0f} + Vec3f{0.0f, 0.0f, 1.0f};
    r.dir = {0.001f * float(i % 7), 0.0f, -1.0f};
    rays.push_back(r);
  }
  for (Isa isa : supported_isas()) {
    for (const Hit& h : trace(isa, bvh, rays)) CHECK_FALSE(h.found());
    for (uint8_t o : trace_occlusion(isa, bvh, rays)) CHECK(o == 0);
  }
}

TEST_CASE("ch02: the BVH2 node keeps both children's planes of an axis in one row") {
  TriangleMesh mesh = one_triangle();
  mesh.vertices.insert(mesh.vertices.end(), {{5, 5, 5}, {6, 5, 5}, {5, 7, 6}});
  mesh.triangles.push_back({3, 4, 5});
  const BVH2 bvh = build(mesh, 1);
  REQUIRE(bvh.nodes.size() == 1);
  CHECK(bvh.root == 0);
  const Node2& n = bvh.nodes[0];
  // The median split on x puts the triangle at the origin left.
  CHECK(std::vector<float>(n.x, n.x + 4) == std::vector<float>{0, 5, 2, 6});
  CHECK(std::vector<float>(n.y, n.y + 4) == std::vector<float>{0, 5, 4, 7});
  CHECK(std::vector<float>(n.z, n.z + 4) == std::vector<float>{0, 5, 0, 6});
  CHECK(is_leaf(n.children[0]));
  CHECK(leaf_blocks(n.children[0]) == 1);
  CHECK(leaf_offset(n.children[1]) == sizeof(Triangle1));
  CHECK(bvh.bytes() == sizeof(Node2) + 2 * sizeof(Triangle1));
}

TEST_CASE("ch02: empty scenes, and what the kernels refuse") {
  const BVH2 empty = make_bvh2(build_median<2>(std::vector<PrimRef>{}, 4), TriangleMesh{});
  const std::vector<Ray> rays = test::random_rays(Box3f(Vec3f(0), Vec3f(1)), 10, 1);
  for (Isa isa : supported_isas()) {
    for (const Hit& h : trace(isa, empty, rays)) CHECK_FALSE(h.found());
    for (uint8_t o : trace_occlusion(isa, empty, rays)) CHECK(o == 0);
  }
  const TriangleMesh mesh = test::make_random_soup(100, 2);
  const BVH2 bvh = build(mesh);
  std::vector<Hit> too_few(rays.size() - 1);
  CHECK_THROWS_AS(intersect(best_isa(), bvh, rays, too_few), std::invalid_argument);
  BVH2 other = bvh;
  other.leaves.layout = "triangle4";
  std::vector<Hit> hits(rays.size());
  CHECK_THROWS_WITH_AS(intersect(best_isa(), other, rays, hits), doctest::Contains("triangle1"),
                       std::invalid_argument);
  // A leaf of more triangles than a reference can count, and a node of three children.
  CHECK_THROWS_AS(make_bvh2(build_median<2>(make_prim_refs(mesh), 40), mesh), std::invalid_argument);
  BuildTree<2> bad = build_median<2>(make_prim_refs(mesh), 4);
  bad.nodes[0].num_children = 1;
  CHECK_THROWS_AS(make_bvh2(bad, mesh), std::invalid_argument);
  bad = build_median<2>(make_prim_refs(mesh), 4);
  bad.prim_ids[0] = 100000;
  CHECK_THROWS_AS(make_bvh2(bad, mesh), std::invalid_argument);
}
