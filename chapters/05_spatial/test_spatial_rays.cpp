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
#include "testing/brute_force.h"
#include "01_base/ray_sets.h"
#include "test_support_ch05.h"

namespace {

using namespace rtk;

/// Traces `rays` through `bvh` with every ISA and checks every answer against the oracle. The
/// Möller-Trumbore kernels round differently from the double-precision oracle on a few grazing
/// rays through slivers, whatever the tree: an answer that misses the oracle's tolerance still
/// passes if it is bit for bit the answer of `object`, the object-split tree's, on the same ISA.
template <class Bvh>
void check_against_oracle(const Bvh& bvh, const Bvh& object, const TriangleMesh& mesh,
                          const std::vector<Ray>& rays) {
  std::vector<Hit> oracle(rays.size());
  std::vector<uint8_t> oracle_occluded(rays.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    oracle[i] = test::brute_force_intersect(mesh, rays[i]);
    oracle_occluded[i] = test::brute_force_occluded(mesh, rays[i]) ? 1 : 0;
  }
  for (const Isa isa : supported_isas()) {
    CAPTURE(std::string(isa_name(isa)));
    std::vector<Hit> hits(rays.size());
    std::vector<uint8_t> blocked(rays.size());
    std::vector<Hit> object_hits(rays.size());
    intersect(isa, bvh, rays, hits);
    occluded(isa, bvh, rays, blocked);
    intersect(isa, object, rays, object_hits);
    int wrong_hits = 0, wrong_occlusion = 0;
    std::string first;
    for (size_t i = 0; i < rays.size(); ++i) {
      std::string why = test::compare_hits(mesh, rays[i], hits[i], oracle[i]);
      if (!why.empty() && hits[i].prim == object_hits[i].prim && hits[i].t == object_hits[i].t) why.clear();
      if (!why.empty() && first.empty()) first = "ray " + std::to_string(i) + ": " + why;
      wrong_hits += why.empty() ? 0 : 1;
      // Where the hit agrees within tolerance, occlusion must agree with it or with the oracle.
      if (why.empty() && blocked[i] != (hits[i].found() ? 1 : 0) && blocked[i] != oracle_occluded[i])
        ++wrong_occlusion;
    }
    CAPTURE(first);
    CHECK(wrong_hits == 0);
    CHECK(wrong_occlusion == 0);
  }
}

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
      check_against_oracle(bvh, object, scene.mesh, test::mixed_rays(scene.mesh.bounds(), 300, 541));
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
        check_against_oracle(bvh, object, scene.mesh, test::mixed_rays(scene.mesh.bounds(), 300, 542));
      }
    }
  }
}
