// Chapter 4: trees from the SAH builder traced by the traversal kernels of the earlier chapters,
// on every ISA the machine runs, against the brute-force oracle.
#include <doctest/doctest.h>

#include <string>
#include <type_traits>
#include <vector>

#include "01_base/cpu_features.h"
#include "02_bvh2/bvh2.h"
#include "02_bvh2/median_builder.h"
#include "03_bvh4/bvh4.h"
#include "04_sah/build_sah.h"
#include "04_sah/test_support_ch04.h"
#include "01_base/ray_sets.h"
#include "testing/scenes.h"

namespace {

using namespace rtk;

struct NamedScene {
  std::string name;
  TriangleMesh mesh;
};

std::vector<NamedScene> scenes() {
  std::vector<NamedScene> s;
  s.push_back({"sphere", test::make_sphere(24, 48)});
  TriangleMesh soup = test::make_random_soup(2500, 51);
  test::add_degenerate_triangles(soup, 100, 52);
  s.push_back({"soup+degenerate", std::move(soup)});
  s.push_back({"terrain", test::make_terrain(32, 53)});
  s.push_back({"slivers", test::make_slivers(1500, 54)});
  return s;
}

}  // namespace

TEST_CASE("ch04: BVH2s made from SAH trees agree with brute force on every ISA") {
  for (const auto& scene : scenes()) {
    CAPTURE(scene.name);
    const std::vector<PrimRef> refs = make_prim_refs(scene.mesh);
    for (const bool rotations : {false, true}) {
      SahBuildOptions options;
      options.rotations = rotations;
      const BVH2 bvh = make_bvh2(build_binned_sah<2>(refs, options), scene.mesh);
      test::check_against_oracle(bvh, scene.mesh, test::mixed_rays(scene.mesh.bounds(), 400, 55));
    }
  }
}

TEST_CASE_TEMPLATE(
    "ch04: BVH4, BVH8 and BVH16 made from SAH trees agree with brute force on every ISA", W,
    std::integral_constant<int, 4>, std::integral_constant<int, 8>,
    std::integral_constant<int, 16>) {
  constexpr int N = W::value;
  for (const auto& scene : scenes()) {
    CAPTURE(scene.name);
    const std::vector<PrimRef> refs = make_prim_refs(scene.mesh);
    for (const OccluderOrder order : {OccluderOrder::off, OccluderOrder::likely_blocker}) {
      SahBuildOptions options;
      options.occluder_order = order;
      const BVHN<N> bvh = make_bvh<N>(build_binned_sah<N>(refs, options), scene.mesh);
      test::check_against_oracle(bvh, scene.mesh, test::mixed_rays(scene.mesh.bounds(), 400, 56));
    }
  }
}

TEST_CASE("ch04: binned SAH trees cost less than median trees") {
  // The SAH builder minimises the cost sah_cost() measures; the median builder ignores it.
  for (const auto& scene : scenes()) {
    CAPTURE(scene.name);
    const std::vector<PrimRef> refs = make_prim_refs(scene.mesh);
    const double median2 = sah_cost(build_median<2>(refs, 8));
    const double median4 = sah_cost(build_median<4>(refs, 8));
    const double binned2 = sah_cost(build_binned_sah<2>(refs));
    const double binned4 = sah_cost(build_binned_sah<4>(refs));
    CHECK(binned2 < median2);
    CHECK(binned4 < median4);
  }
}
