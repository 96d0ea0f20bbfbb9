// Chapter 9: rays in packets give, ray for ray and bit for bit, the answers of chapter 3's
// one-ray-at-a-time traversal with the same leaves, on every ISA, for BVH4 and BVH8 with
// triangle4 and triangle8 leaves, whatever the batch's size and whichever rays are invalid.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "01_base/cpu_features.h"
#include "06_layouts/test_support_ch06.h"
#include "07_intersectors/layout_intersectors.h"
#include "09_inflight/packets.h"
#include "replay/ray_generator.h"
#include "testing/brute_force.h"

using namespace rtk;

namespace {

struct RaySet {
  std::string name;
  std::vector<Ray> rays;
};

/// Rays straight down onto a lattice over the scene's box, every one of one octant: on the
/// terrain they pass through its grid's vertices and edges, where triangles tie at equal t.
std::vector<Ray> lattice_rays(const Box3f& box, int n) {
  std::vector<Ray> rays;
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k <= n; ++k) {
      Ray ray;
      ray.org = {box.lower.x + (box.upper.x - box.lower.x) * float(i) / float(n), box.upper.y + 1.0f,
                 box.lower.z + (box.upper.z - box.lower.z) * float(k) / float(n)};
      ray.dir = {0.0f, -1.0f, 0.0f};
      rays.push_back(ray);
    }
  return rays;
}

std::vector<RaySet> ray_sets(const test::LayoutScene& scene) {
  std::vector<RaySet> sets;
  sets.push_back({"primary", generate_rays(scene.mesh, RayKind::primary, 1001, 7)});
  sets.push_back({"shadow", generate_rays(scene.mesh, RayKind::shadow, 205, 9)});
  sets.push_back({"diffuse", generate_rays(scene.mesh, RayKind::diffuse, 203, 8)});
  sets.push_back({"lattice", lattice_rays(scene.mesh.bounds(), 36)});
  sets.push_back({"mixed", scene.rays});
  // Every third primary ray made invalid: packets with holes.
  RaySet holes{"primary with invalid rays", sets.front().rays};
  const std::vector<Ray> invalid = test::invalid_rays();
  for (size_t i = 0; i < holes.rays.size(); i += 3) holes.rays[i] = invalid[i % invalid.size()];
  sets.push_back(holes);
  return sets;
}

/// Groups of P consecutive rays of one octant with two valid rays or more: those the kernels
/// trace as packets.
size_t packet_groups(std::span<const Ray> rays, int p) {
  auto octant = [](const Ray& r) { return std::signbit(r.dir.x) | std::signbit(r.dir.y) << 1 | std::signbit(r.dir.z) << 2; };
  size_t groups = 0;
  for (size_t first = 0; first < rays.size(); first += size_t(p)) {
    int valid = 0;
    bool one_octant = true;
    for (size_t i = first; i < std::min(rays.size(), first + size_t(p)); ++i) {
      valid += is_valid(rays[i]);
      one_octant = one_octant && octant(rays[i]) == octant(rays[first]);
    }
    groups += valid >= 2 && one_octant;
  }
  return groups;
}

template <int N>
void check_same_bits(const LayoutBVH<N>& bvh, const RaySet& set, size_t& packets) {
  CAPTURE(set.name);
  std::vector<Hit> reference(set.rays.size());
  std::vector<uint8_t> blocked(set.rays.size());
  intersect(Isa::scalar, bvh, IntersectorKind::moeller, set.rays, reference);
  occluded(Isa::scalar, bvh, IntersectorKind::moeller, set.rays, blocked);
  for (const Isa isa : supported_isas()) {
    if (!has_packets(isa, {bvh.layout, IntersectorKind::moeller})) continue;
    CAPTURE(isa_name(isa));
    for (size_t n : {size_t(0), size_t(1), size_t(2), size_t(5), size_t(17), set.rays.size()}) {
      CAPTURE(n);
      const std::span<const Ray> rays(set.rays.data(), n);
      packets += packet_groups(rays, packet_width(isa));
      // Every answer must be written: start from values no kernel writes.
      Hit poison;
      poison.t = poison.u = poison.v = -7.0f;
      poison.prim = 0x5a5a5a5a;
      std::vector<Hit> hits(n, poison);
      std::vector<uint8_t> occ(n, 7);
      intersect_packets<N>(isa, bvh, IntersectorKind::moeller, rays, hits);
      occluded_packets<N>(isa, bvh, IntersectorKind::moeller, rays, occ);
      int differ = 0;
      for (size_t i = 0; i < n; ++i) differ += !test::same_bits(hits[i], reference[i]) || occ[i] != blocked[i];
      CHECK(differ == 0);
    }
  }
}

template <int N>
void check_width() {
  size_t packets = 0;
  for (const test::LayoutScene& scene : test::layout_scenes()) {
    CAPTURE(scene.name);
    const BuildTree<N> tree = test::sah_tree<N>(scene.mesh);
    const std::vector<RaySet> sets = ray_sets(scene);
    for (const TriangleLayout layout : {TriangleLayout::triangle8, TriangleLayout::triangle4}) {
      CAPTURE(layout_name(layout));
      const LayoutBVH<N> bvh = make_layout_bvh<N>(tree, scene.mesh, layout);
      for (const RaySet& set : sets) check_same_bits(bvh, set, packets);
    }
  }
  // The comparison must have run packets, not only the single-ray fallback.
  if (has_packets(best_isa(), {TriangleLayout::triangle8, IntersectorKind::moeller})) CHECK(packets > 1000);
}

}  // namespace

// [ch09-test-packets]
TEST_CASE("ch09: packets give chapter 3's bits in BVH8, triangle8 and triangle4 leaves, on every ISA") { check_width<8>(); }
TEST_CASE("ch09: packets give chapter 3's bits in BVH4, triangle8 and triangle4 leaves, on every ISA") { check_width<4>(); }
// [ch09-test-packets]

TEST_CASE("ch09: packets exist for Moeller-Trumbore on triangle4 and triangle8 only, and not on the scalar ISA") {
  CHECK(!has_packets(Isa::scalar, {TriangleLayout::triangle8, IntersectorKind::moeller}));
  for (const Isa isa : supported_isas()) {
    if (isa == Isa::scalar) continue;
    CAPTURE(isa_name(isa));
    CHECK(has_packets(isa, {TriangleLayout::triangle8, IntersectorKind::moeller}));
    CHECK(has_packets(isa, {TriangleLayout::triangle4, IntersectorKind::moeller}));
    CHECK(!has_packets(isa, {TriangleLayout::triangle1, IntersectorKind::moeller}));
    CHECK(!has_packets(isa, {TriangleLayout::triangle4v, IntersectorKind::watertight}));
  }
}

TEST_CASE("ch09: packets in an empty scene miss; mismatched spans are refused") {
  const TriangleMesh empty;
  const LayoutBVH<8> bvh = make_layout_bvh<8>(test::sah_tree<8>(empty), empty, TriangleLayout::triangle8);
  std::vector<Ray> rays(40);
  for (size_t i = 0; i < rays.size(); ++i) rays[i].org = {float(i), 0, 0}, rays[i].dir = {0, 0, 1};
  for (const Isa isa : supported_isas()) {
    if (!has_packets(isa, {TriangleLayout::triangle8, IntersectorKind::moeller})) continue;
    std::vector<Hit> hits(rays.size());
    std::vector<uint8_t> occ(rays.size(), 1);
    intersect_packets<8>(isa, bvh, IntersectorKind::moeller, rays, hits);
    occluded_packets<8>(isa, bvh, IntersectorKind::moeller, rays, occ);
    for (size_t i = 0; i < rays.size(); ++i) CHECK((!hits[i].found() && occ[i] == 0));
    std::vector<Hit> short_hits(rays.size() - 1);
    CHECK_THROWS_AS(intersect_packets<8>(isa, bvh, IntersectorKind::moeller, rays, short_hits), std::invalid_argument);
  }
}
