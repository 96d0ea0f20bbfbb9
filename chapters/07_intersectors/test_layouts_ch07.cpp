// Chapter 7: the intersectors in chapter 6's layouts, through BVH2, BVH4 and BVH8: against the
// oracle, ISA against ISA, layout against layout, width against width, and no leak that the
// intersector alone would not make.
#include <doctest/doctest.h>

#include <stdexcept>
#include <vector>

#include "05_spatial/build_spatial.h"
#include "06_layouts/layout_build.h"
#include "06_layouts/test_support_ch06.h"
#include "07_intersectors/accuracy_scene.h"
#include "07_intersectors/intersect_all.h"
#include "07_intersectors/layout_intersectors.h"
#include "07_intersectors/stability_meshes.h"
#include "07_intersectors/triangle_soa.h"
#include "testing/sanitizer_build.h"

using namespace rtk;

namespace {

template <int N>
void check_every_config(const test::LayoutScene& scene) {
  const BuildTree<N> tree = test::sah_tree<N>(scene.mesh);
  for (const TriangleConfig& config : supported_triangle_configs()) {
    CAPTURE(scene.name);
    CAPTURE(N);
    CAPTURE(config.name());
    const LayoutBVH<N> bvh = make_layout_bvh<N>(tree, scene.mesh, config.layout);
    test::check_every_isa(
        scene, [&](Isa isa, auto rays, auto hits) { intersect(isa, bvh, config.intersector, rays, hits); },
        [&](Isa isa, auto rays, auto blocked) { occluded(isa, bvh, config.intersector, rays, blocked); });
  }
}

// The scene's hits and occlusion through a LayoutBVH<N> in `config`, built with the SAH options
// of its layout and object splits (chapter 4) or spatial splits too (chapter 5).
template <int N>
void trace_width(const test::LayoutScene& scene, const TriangleConfig& config, bool spatial,
                 std::vector<Hit>& hits, std::vector<uint8_t>& blocked) {
  SahBuildOptions sah = sah_options_for(config.layout);
  sah.threads = 1;
  SpatialBuildOptions options;
  options.sah = sah;
  const BuildTree<N> tree = spatial ? build_spatial_sah<N>(scene.mesh, options)
                                    : build_binned_sah<N>(make_prim_refs(scene.mesh), sah);
  const LayoutBVH<N> bvh = make_layout_bvh<N>(tree, scene.mesh, config.layout);
  intersect(best_isa(), bvh, config.intersector, scene.rays, hits);
  occluded(best_isa(), bvh, config.intersector, scene.rays, blocked);
}

}  // namespace

TEST_CASE("ch07: every layout and intersector agrees with the oracle through BVH2, every ISA bit for bit") {
  for (const test::LayoutScene& scene : test::layout_scenes()) check_every_config<2>(scene);
}

TEST_CASE("ch07: every layout and intersector agrees with the oracle through BVH4, every ISA bit for bit") {
  for (const test::LayoutScene& scene : test::layout_scenes()) check_every_config<4>(scene);
}

TEST_CASE("ch07: every layout and intersector agrees with the oracle through BVH8, every ISA bit for bit") {
  for (const test::LayoutScene& scene : test::layout_scenes()) check_every_config<8>(scene);
}

TEST_CASE("ch07: for one intersector, every layout that has it finds the same hits bit for bit") {
  for (const test::LayoutScene& scene : test::layout_scenes()) {
    const BuildTree<4> tree = test::sah_tree<4>(scene.mesh);
    for (const IntersectorKind kind : kAllIntersectors) {
      std::vector<Hit> first;
      for (const TriangleLayout layout : kAllLayouts) {
        if (!layout_supports(layout, kind)) continue;
        CAPTURE(scene.name);
        CAPTURE(layout_name(layout));
        CAPTURE(intersector_name(kind));
        const LayoutBVH<4> bvh = make_layout_bvh<4>(tree, scene.mesh, layout);
        std::vector<Hit> hits(scene.rays.size());
        intersect(best_isa(), bvh, kind, scene.rays, hits);
        if (first.empty()) {
          first = hits;
          continue;
        }
        int differ = 0;
        for (size_t i = 0; i < hits.size(); ++i) differ += !test::same_bits(hits[i], first[i]);
        CHECK(differ == 0);
      }
    }
  }
}

TEST_CASE("ch07: every configuration finds the same hits through BVH2, BVH4 and BVH8") {
  // Object and spatial splits, every layout and intersector: the tree and the node width change
  // the order the triangles are met in, never the answer.
  for (const test::LayoutScene& scene : test::layout_scenes())
    for (const bool spatial : {false, true})
      for (const TriangleConfig& config : supported_triangle_configs()) {
        CAPTURE(scene.name);
        CAPTURE(spatial);
        CAPTURE(config.name());
        const size_t n = scene.rays.size();
        std::vector<Hit> reference(n), hits(n);
        std::vector<uint8_t> reference_blocked(n), blocked(n);
        trace_width<4>(scene, config, spatial, reference, reference_blocked);
        for (const int width : {2, 8}) {
          CAPTURE(width);
          if (width == 2) trace_width<2>(scene, config, spatial, hits, blocked);
          else trace_width<8>(scene, config, spatial, hits, blocked);
          int differ = 0;
          for (size_t i = 0; i < n; ++i)
            differ += !test::same_bits(hits[i], reference[i]) || blocked[i] != reference_blocked[i];
          CHECK(differ == 0);
        }
      }
}

// [ch07-test-no-new-leaks]
TEST_CASE("ch07: through BVH2, BVH4 and BVH8 no ray leaks that the intersector alone would hit") {
  // Rays from inside the accuracy scene's spindle at its vertices and edges (every sixth of
  // them). Hit or miss is decided by the intersector alone when the traversal never culls a
  // box its triangle's hit lies in: so each configuration leaks exactly the rays that the
  // intersector leaks against every triangle, and the watertight ones leak none.
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
      intersect(best_isa(), build_layout_bvh<4>(mesh, layout, 1), kind, rays, hits);
      CHECK(count_misses(hits) == expected);
      intersect(best_isa(), build_layout_bvh<8>(mesh, layout, 1), kind, rays, hits);
      CHECK(count_misses(hits) == expected);
      intersect(best_isa(), build_layout_bvh<2>(mesh, layout, 1), kind, rays, hits);
      CHECK(count_misses(hits) == expected);
    }
    if (kind == IntersectorKind::watertight) CHECK(expected == 0);
  }
}
// [ch07-test-no-new-leaks]

TEST_CASE("ch07: a precomputed layout refuses the tests that need vertices") {
  const TriangleMesh mesh = test::make_sphere(4, 8);
  const LayoutBVH<4> bvh = make_layout_bvh<4>(test::sah_tree<4>(mesh), mesh, TriangleLayout::triangle4);
  std::vector<Ray> rays(3);
  std::vector<Hit> hits(3);
  CHECK_THROWS_AS(intersect(Isa::scalar, bvh, IntersectorKind::pluecker, rays, hits), std::invalid_argument);
}
