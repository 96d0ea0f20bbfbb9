// Chapter 5: trees with spatial splits traced by the BVH2, BVH4 and BVH8 kernels of chapters 2
// and 3 on every ISA the machine runs, against the brute-force oracle. A triangle referenced by
// several leaves must still give the closest hit once, and occlusion must agree.
#include <doctest/doctest.h>

#include <string>
#include <type_traits>
#include <vector>

#include "01_base/cpu_features.h"
#include "02_bvh2/bvh2.h"
#include "03_bvh4/bvh4.h"
#include "04_sah/build_sah.h"
#include "05_spatial/build_spatial.h"
#include "04_sah/test_support_ch04.h"
#include "01_base/ray_sets.h"
#include "test_support_ch05.h"

namespace {

using namespace rtk;

constexpr SpatialSplitMode kModes[] = {SpatialSplitMode::centre, SpatialSplitMode::binned};

}  // namespace

TEST_CASE("ch05: BVH2s over spatial-split trees agree with brute force on every ISA") {
  for (const auto& scene : test::spatial_scenes()) {
    CAPTURE(scene.name);
    for (const SpatialSplitMode mode : kModes) {
      SpatialBuildOptions options;
      options.mode = mode;
      options.budget = 1.0f;  // many duplicates: the case to test
      SpatialBuildStats stats;
      const BVH2 bvh = make_bvh2(build_spatial_sah<2>(scene.mesh, options, &stats), scene.mesh);
      const BVH2 object = make_bvh2(build_binned_sah<2>(make_prim_refs(scene.mesh)), scene.mesh);
      test::check_against_oracle(bvh, scene.mesh, test::mixed_rays(scene.mesh.bounds(), 300, 541), &object);
    }
  }
}

TEST_CASE_TEMPLATE("ch05: BVH4s and BVH8s over spatial-split trees agree with brute force on every ISA", W,
                   std::integral_constant<int, 4>, std::integral_constant<int, 8>) {
  constexpr int N = W::value;
  for (const auto& scene : test::spatial_scenes()) {
    CAPTURE(scene.name);
    for (const SpatialSplitMode mode : kModes) {
      for (const float budget : {0.3f, 1.0f}) {
        SpatialBuildOptions options;
        options.mode = mode;
        options.budget = budget;
        SpatialBuildStats stats;
        const BVHN<N> bvh = make_bvh<N>(build_spatial_sah<N>(scene.mesh, options, &stats), scene.mesh);
        const BVHN<N> object = make_bvh<N>(build_binned_sah<N>(make_prim_refs(scene.mesh)), scene.mesh);
        if (budget == 1.0f && scene.name == "slivers") CHECK(stats.references > stats.triangles);
        test::check_against_oracle(bvh, scene.mesh, test::mixed_rays(scene.mesh.bounds(), 300, 542), &object);
      }
    }
  }
}
