// Chapter 6: every layout with every intersector it supports, through chapter 3's BVH4 and
// BVH8, against the brute-force oracle, ISA against ISA, and layout against layout.
#include <doctest/doctest.h>

#include <bit>
#include <cstring>
#include <string>
#include <vector>

#include "04_sah/build_sah.h"
#include "06_layouts/layout_build.h"
#include "06_layouts/triangle_i.h"
#include "06_layouts/triangle_m.h"
#include "06_layouts/triangle_v.h"
#include "07_intersectors/accuracy_scene.h"
#include "07_intersectors/intersect_all.h"
#include "07_intersectors/stability_meshes.h"
#include "testing/brute_force.h"
#include "01_base/ray_sets.h"
#include "testing/sanitizer_build.h"
#include "testing/scenes.h"

namespace {

using namespace rtk;

struct Scene {
  std::string name;
  TriangleMesh mesh;
  std::vector<Ray> rays;
};

std::vector<Scene> scenes() {
  std::vector<Scene> out;
  out.push_back({"sphere", test::make_sphere(12, 24, {0.5f, 0.5f, 0.5f}, 0.4f), {}});
  out.push_back({"soup", test::make_random_soup(400, 61), {}});
  out.push_back({"terrain", test::make_terrain(12, 62), {}});
  out.push_back({"slivers", test::make_slivers(200, 63), {}});
  test::add_degenerate_triangles(out.back().mesh, 25, 64);
  for (Scene& s : out) s.rays = test::mixed_rays(s.mesh.bounds(), 240, 65);
  return out;
}

template <int N>
BuildTree<N> build(const TriangleMesh& mesh) {
  SahBuildOptions options;
  options.threads = 1;
  return build_binned_sah<N>(make_prim_refs(mesh), options);
}

bool same_bits(const Hit& a, const Hit& b) {
  return std::bit_cast<uint32_t>(a.t) == std::bit_cast<uint32_t>(b.t) &&
         std::bit_cast<uint32_t>(a.u) == std::bit_cast<uint32_t>(b.u) &&
         std::bit_cast<uint32_t>(a.v) == std::bit_cast<uint32_t>(b.v) && a.prim == b.prim;
}

template <int N>
void check_against_oracle(const Scene& scene) {
  const BuildTree<N> tree = build<N>(scene.mesh);
  std::vector<Hit> oracle;
  for (const Ray& r : scene.rays) oracle.push_back(test::brute_force_intersect(scene.mesh, r));
  for (const TriangleConfig& config : supported_triangle_configs()) {
    CAPTURE(scene.name);
    CAPTURE(N);
    CAPTURE(config.name());
    const LayoutBVH<N> bvh = make_layout_bvh<N>(tree, scene.mesh, config);
    std::vector<Hit> reference(scene.rays.size());
    std::vector<uint8_t> blocked(scene.rays.size());
    intersect(Isa::scalar, bvh, scene.rays, reference);
    occluded(Isa::scalar, bvh, scene.rays, blocked);
    for (size_t i = 0; i < scene.rays.size(); ++i) {
      CHECK_MESSAGE(test::compare_hits(scene.mesh, scene.rays[i], reference[i], oracle[i]) == "", i);
      CHECK(bool(blocked[i]) == reference[i].found());  // one kernel, one decision
    }
    for (const Isa isa : supported_isas()) {
      CAPTURE(isa_name(isa));
      std::vector<Hit> hits(scene.rays.size());
      std::vector<uint8_t> isa_blocked(scene.rays.size());
      intersect(isa, bvh, scene.rays, hits);
      occluded(isa, bvh, scene.rays, isa_blocked);
      int differ = 0;
      for (size_t i = 0; i < hits.size(); ++i)
        differ += !same_bits(hits[i], reference[i]) || isa_blocked[i] != blocked[i];
      CHECK(differ == 0);
    }
  }
}

}  // namespace

TEST_CASE("ch06: every layout and intersector agrees with the oracle through BVH4, every ISA bit for bit") {
  for (const Scene& scene : scenes()) check_against_oracle<4>(scene);
}

TEST_CASE("ch06: every layout and intersector agrees with the oracle through BVH8, every ISA bit for bit") {
  for (const Scene& scene : scenes()) check_against_oracle<8>(scene);
}

// [ch06-test-same-hits]
TEST_CASE("ch06: for one intersector, every layout finds the same hits bit for bit") {
  // Same tree, same leaf order, the same float operations on the same inputs: whether the
  // edges are precomputed or computed per ray, and whether the block holds 1, 4 or 8
  // triangles, changes nothing in the answer, only in the time and the memory.
  for (const Scene& scene : scenes()) {
    const BuildTree<4> tree = build<4>(scene.mesh);
    for (const IntersectorKind kind : kAllIntersectors) {
      std::vector<Hit> first;
      for (const TriangleLayout layout : kAllLayouts) {
        if (!layout_supports(layout, kind)) continue;
        CAPTURE(scene.name);
        CAPTURE(layout_name(layout));
        CAPTURE(intersector_name(kind));
        const LayoutBVH<4> bvh = make_layout_bvh<4>(tree, scene.mesh, {layout, kind});
        std::vector<Hit> hits(scene.rays.size());
        intersect(best_isa(), bvh, scene.rays, hits);
        if (first.empty()) {
          first = hits;
          continue;
        }
        int differ = 0;
        for (size_t i = 0; i < hits.size(); ++i) differ += !same_bits(hits[i], first[i]);
        CHECK(differ == 0);
      }
    }
  }
}
// [ch06-test-same-hits]

// [ch06-test-no-new-leaks]
TEST_CASE("ch06: through BVH4 and BVH8 no ray leaks that brute force would hit") {
  // Rays from inside the accuracy scene's spindle at its vertices and edges (every sixth of
  // them). Hit or miss is decided by the intersector alone when the traversal never culls a
  // box its triangle's hit lies in: so each configuration leaks exactly the rays that brute
  // force with its intersector leaks, and the watertight ones leak none.
  const TriangleMesh mesh = make_accuracy_scene().mesh;
  const std::vector<Ray> all = accuracy_inside_rays();
  std::vector<Ray> rays;
  for (size_t i = 0; i < all.size(); i += test::kSanitizerBuild ? 96 : 6) rays.push_back(all[i]);
  const TriangleSoA soa(mesh);
  for (const IntersectorKind kind : kAllIntersectors) {
    std::vector<Hit> brute(rays.size());
    RTK_PICK_ISA(best_isa(), intersect_all)(soa, kind, 16, rays, brute);
    const size_t expected = count_misses(brute);
    for (const TriangleLayout layout : kAllLayouts) {
      if (!layout_supports(layout, kind)) continue;
      CAPTURE(layout_name(layout));
      CAPTURE(intersector_name(kind));
      std::vector<Hit> hits(rays.size());
      intersect(best_isa(), build_layout_bvh<4>(mesh, {layout, kind}, 1), rays, hits);
      CHECK(count_misses(hits) == expected);
      intersect(best_isa(), build_layout_bvh<8>(mesh, {layout, kind}, 1), rays, hits);
      CHECK(count_misses(hits) == expected);
    }
    if (kind == IntersectorKind::watertight) CHECK(expected == 0);
  }
}
// [ch06-test-no-new-leaks]

TEST_CASE("ch06: bytes per triangle") {
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle1) == 48);
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle4) == 52);
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle8) == 52);
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle1v) == 48);
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle4v) == 40);
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle1i) == 32);
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle4i) == 20);
  // On a closed mesh (about two triangles per vertex), each layout with the tree its blocks
  // want (sah_options_for): the indexed blocks are the leanest in all, shared vertices
  // counted, and the precomputed ones the largest.
  const TriangleMesh sphere = test::make_sphere(64, 128);
  auto bytes = [&](TriangleLayout layout) {
    const LayoutBVH<4> bvh = build_layout_bvh<4>(sphere, {layout, IntersectorKind::moeller}, 1);
    const double b = double(bvh.bytes()) / double(sphere.size());
    MESSAGE(layout_name(layout) << ": " << b << " bytes per triangle (BVH4 nodes included)");
    CHECK(b <= estimated_bytes_per_triangle(layout));
    return b;
  };
  const double t4i = bytes(TriangleLayout::triangle4i), t4v = bytes(TriangleLayout::triangle4v);
  const double t4 = bytes(TriangleLayout::triangle4), t1i = bytes(TriangleLayout::triangle1i);
  const double t1 = bytes(TriangleLayout::triangle1), t8 = bytes(TriangleLayout::triangle8);
  CHECK(t4i < t1i);
  CHECK(t4i < t4v);
  CHECK(t4v < t4);
  CHECK(t4 < t1);  // blocks of four need fewer nodes above them
  CHECK(t8 > t4);  // and blocks of eight pad more
  CHECK(bytes(TriangleLayout::triangle1v) == t1);
}

TEST_CASE("ch06: the indexed layouts keep their own copy of the vertices") {
  TriangleMesh mesh = test::make_sphere(10, 20);
  const std::vector<Ray> rays = test::random_rays(mesh.bounds(), 100, 66);
  const BuildTree<8> tree = build<8>(mesh);
  const LayoutBVH<8> reference = make_layout_bvh<8>(tree, mesh, {TriangleLayout::triangle1v, IntersectorKind::watertight});
  LayoutBVH<8> indexed = make_layout_bvh<8>(tree, mesh, {TriangleLayout::triangle4i, IntersectorKind::watertight});
  mesh = TriangleMesh{};  // the original goes away
  const LayoutBVH<8> moved = std::move(indexed);
  std::vector<Hit> a(rays.size()), b(rays.size());
  intersect(best_isa(), reference, rays, a);
  intersect(best_isa(), moved, rays, b);
  for (size_t i = 0; i < rays.size(); ++i) CHECK(same_bits(a[i], b[i]));
}

TEST_CASE("ch06: unsupported configurations and mismatched spans are refused") {
  const TriangleMesh mesh = test::make_sphere(4, 8);
  const BuildTree<4> tree = build<4>(mesh);
  CHECK_THROWS_AS(make_layout_bvh<4>(tree, mesh, {TriangleLayout::triangle4, IntersectorKind::pluecker}),
                  std::invalid_argument);
  const LayoutBVH<4> bvh = make_layout_bvh<4>(tree, mesh, {TriangleLayout::triangle4, IntersectorKind::moeller});
  std::vector<Ray> rays(3);
  std::vector<Hit> hits(2);
  CHECK_THROWS_AS(intersect(Isa::scalar, bvh, rays, hits), std::invalid_argument);
}
