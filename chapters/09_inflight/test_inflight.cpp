// Chapter 9: rays in flight give, ray for ray and bit for bit, the answers of chapter 3's
// one-ray-at-a-time traversal with the same leaf intersector, on every ISA, for every number of
// rays in flight, with and without prefetching, whatever the batch's size.
#include <doctest/doctest.h>

#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "01_base/cpu_features.h"
#include "06_layouts/test_support_ch06.h"
#include "07_intersectors/layout_intersectors.h"
#include "09_inflight/inflight.h"
#include "replay/ray_generator.h"
#include "testing/brute_force.h"

using namespace rtk;

namespace {

struct RaySet {
  std::string name;
  std::vector<Ray> rays;
};

// The rays of the benchmarks (primary rays from a camera outside, many of which miss; diffuse
// rays leaving the surfaces; shadow rays toward a light above), and the tests' hard cases
// (axis-aligned, grazing, NaN and infinite rays, finite intervals). Sizes are not multiples of
// any number of rays in flight.
std::vector<RaySet> ray_sets(const test::LayoutScene& scene) {
  std::vector<RaySet> sets;
  sets.push_back({"primary", generate_rays(scene.mesh, RayKind::primary, 301, 7)});
  sets.push_back({"diffuse", generate_rays(scene.mesh, RayKind::diffuse, 203, 8)});
  sets.push_back({"shadow", generate_rays(scene.mesh, RayKind::shadow, 205, 9)});
  sets.push_back({"mixed", scene.rays});
  return sets;
}

// Compares the in-flight kernels of every ISA with chapter 7's single-ray kernels of the scalar
// ISA, on the whole set and on its first few rays (batches of 0 to 9: fewer rays than slots).
void check_same_bits(const LayoutBVH<8>& bvh, IntersectorKind kind, InflightConfig config, const RaySet& set) {
  CAPTURE(set.name);
  CAPTURE(config.name());
  std::vector<Hit> reference(set.rays.size());
  std::vector<uint8_t> blocked(set.rays.size());
  intersect(Isa::scalar, bvh, kind, set.rays, reference);
  occluded(Isa::scalar, bvh, kind, set.rays, blocked);
  for (const Isa isa : supported_isas()) {
    CAPTURE(isa_name(isa));
    for (size_t n : {size_t(0), size_t(1), size_t(2), size_t(3), size_t(5), size_t(9), set.rays.size()}) {
      CAPTURE(n);
      const std::span<const Ray> rays(set.rays.data(), n);
      // Every answer must be written: start from values no kernel writes.
      Hit poison;
      poison.t = poison.u = poison.v = -7.0f;
      poison.prim = 0x5a5a5a5a;
      std::vector<Hit> hits(n, poison);
      std::vector<uint8_t> occ(n, 7);
      intersect_inflight(isa, bvh, kind, config, rays, hits);
      occluded_inflight(isa, bvh, kind, config, rays, occ);
      int differ = 0;
      for (size_t i = 0; i < n; ++i) differ += !test::same_bits(hits[i], reference[i]) || occ[i] != blocked[i];
      CHECK(differ == 0);
    }
  }
}

}  // namespace

// [ch09-test-ablation]
TEST_CASE("ch09: 1, 2, 4 and 8 rays in flight, with and without prefetch, give chapter 3's bits on every ISA") {
  for (const test::LayoutScene& scene : test::layout_scenes()) {
    CAPTURE(scene.name);
    const BuildTree<8> tree = test::sah_tree<8>(scene.mesh);
    const std::vector<RaySet> sets = ray_sets(scene);
    for (const TriangleLayout layout : {TriangleLayout::triangle8, TriangleLayout::triangle4}) {
      CAPTURE(layout_name(layout));
      const LayoutBVH<8> bvh = make_layout_bvh<8>(tree, scene.mesh, layout);
      for (const InflightConfig& config : kInflightConfigs)
        for (const RaySet& set : sets) check_same_bits(bvh, IntersectorKind::moeller, config, set);
    }
  }
}
// [ch09-test-ablation]

TEST_CASE("ch09: every layout and intersector in flight gives its single-ray bits on every ISA") {
  for (const test::LayoutScene& scene : test::layout_scenes()) {
    CAPTURE(scene.name);
    const BuildTree<8> tree = test::sah_tree<8>(scene.mesh);
    const std::vector<RaySet> sets = ray_sets(scene);
    for (const TriangleConfig& tri : supported_triangle_configs()) {
      CAPTURE(tri.name());
      const LayoutBVH<8> bvh = make_layout_bvh<8>(tree, scene.mesh, tri.layout);
      for (const RaySet& set : sets) check_same_bits(bvh, tri.intersector, kDefaultInflight, set);
    }
  }
}

TEST_CASE("ch09: rays that are not rays miss, alone or between valid ones, and a hit is still a hit") {
  const test::LayoutScene scene = test::layout_scenes().front();
  const LayoutBVH<8> bvh = make_layout_bvh<8>(test::sah_tree<8>(scene.mesh), scene.mesh, TriangleLayout::triangle8);
  const std::vector<Ray> invalid = test::invalid_rays();
  REQUIRE(!invalid.empty());
  // Valid rays through the sphere's centre, each followed by an invalid one.
  std::vector<Ray> mixed;
  for (size_t i = 0; i < invalid.size(); ++i) {
    Ray ray;
    ray.org = {0.5f + 0.01f * float(i % 7), 0.5f, -1.0f};
    ray.dir = {0.0f, 0.0f, 1.0f};
    mixed.push_back(ray);
    mixed.push_back(invalid[i]);
  }
  for (const Isa isa : supported_isas())
    for (const InflightConfig& config : kInflightConfigs) {
      CAPTURE(isa_name(isa));
      CAPTURE(config.name());
      std::vector<Hit> hits(invalid.size());
      std::vector<uint8_t> occ(invalid.size(), 1);
      intersect_inflight(isa, bvh, IntersectorKind::moeller, config, invalid, hits);
      occluded_inflight(isa, bvh, IntersectorKind::moeller, config, invalid, occ);
      for (size_t i = 0; i < invalid.size(); ++i) {
        CHECK(!hits[i].found());
        CHECK(occ[i] == 0);
      }
      std::vector<Hit> mixed_hits(mixed.size());
      std::vector<uint8_t> mixed_occ(mixed.size());
      intersect_inflight(isa, bvh, IntersectorKind::moeller, config, mixed, mixed_hits);
      occluded_inflight(isa, bvh, IntersectorKind::moeller, config, mixed, mixed_occ);
      for (size_t i = 0; i < mixed.size(); ++i) {
        CHECK(mixed_hits[i].found() == (i % 2 == 0));
        CHECK(mixed_occ[i] == (i % 2 == 0 ? 1 : 0));
      }
    }
}

TEST_CASE("ch09: an empty scene misses every ray; mismatched spans and configurations not compiled are refused") {
  const TriangleMesh empty;
  const LayoutBVH<8> bvh = make_layout_bvh<8>(test::sah_tree<8>(empty), empty, TriangleLayout::triangle8);
  const std::vector<Ray> rays = test::mixed_rays(Box3f(Vec3f(0.0f), Vec3f(1.0f)), 40, 3);
  for (const InflightConfig& config : kInflightConfigs) {
    std::vector<Hit> hits(rays.size());
    std::vector<uint8_t> occ(rays.size(), 1);
    intersect_inflight(best_isa(), bvh, IntersectorKind::moeller, config, rays, hits);
    occluded_inflight(best_isa(), bvh, IntersectorKind::moeller, config, rays, occ);
    for (size_t i = 0; i < rays.size(); ++i) CHECK((!hits[i].found() && occ[i] == 0));
  }
  std::vector<Hit> short_hits(rays.size() - 1);
  CHECK_THROWS_AS(intersect_inflight(best_isa(), bvh, IntersectorKind::moeller, kDefaultInflight, rays, short_hits),
                  std::invalid_argument);
  const TriangleConfig vertex{TriangleLayout::triangle4v, IntersectorKind::watertight};
  CHECK(inflight_compiled(vertex, kDefaultInflight));
  CHECK(!inflight_compiled(vertex, {8, false}));
  CHECK(inflight_compiled({TriangleLayout::triangle8, IntersectorKind::moeller}, {8, false}));
  CHECK(!inflight_compiled({TriangleLayout::triangle8, IntersectorKind::pluecker}, kDefaultInflight));
  CHECK_THROWS_AS(RTK_PICK_ISA(best_isa(), inflight_kernels<8>)(vertex, {8, false}), std::invalid_argument);
  CHECK_THROWS_AS(RTK_PICK_ISA(best_isa(), inflight_kernels<8>)({TriangleLayout::triangle8, IntersectorKind::pluecker},
                                                               kDefaultInflight),
                  std::invalid_argument);
}
