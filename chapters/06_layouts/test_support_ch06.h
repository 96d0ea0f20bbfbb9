// What chapters 6 and 7 test every layout with: small procedural scenes with hard rays, and the
// check that a layout BVH agrees with the brute-force oracle and that every ISA gives the same
// bits as the scalar variant.
#pragma once

#include <doctest/doctest.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "01_base/cpu_features.h"
#include "01_base/ray_sets.h"
#include "04_sah/build_sah.h"
#include "06_layouts/layout_bvh.h"
#include "testing/brute_force.h"
#include "testing/scenes.h"

namespace rtk::test {

struct LayoutScene {
  std::string name;
  TriangleMesh mesh;
  std::vector<Ray> rays;
};

/// A closed sphere, a soup, a terrain and slivers with zero-area triangles, with mixed rays.
inline std::vector<LayoutScene> layout_scenes() {
  std::vector<LayoutScene> out;
  out.push_back({"sphere", make_sphere(12, 24, {0.5f, 0.5f, 0.5f}, 0.4f), {}});
  out.push_back({"soup", make_random_soup(400, 61), {}});
  out.push_back({"terrain", make_terrain(12, 62), {}});
  out.push_back({"slivers", make_slivers(200, 63), {}});
  add_degenerate_triangles(out.back().mesh, 25, 64);
  for (LayoutScene& s : out) s.rays = mixed_rays(s.mesh.bounds(), 240, 65);
  return out;
}

/// Chapter 4's binned SAH tree, on one thread.
template <int N>
BuildTree<N> sah_tree(const TriangleMesh& mesh) {
  SahBuildOptions options;
  options.threads = 1;
  return build_binned_sah<N>(make_prim_refs(mesh), options);
}

/// Traces the scene's rays with `intersect(isa, rays, hits)` and `occluded(isa, rays, blocked)`
/// (spans): the scalar variant agrees with the oracle and with itself (a hit exactly when
/// blocked), and every other ISA gives its bits.
template <class Intersect, class Occluded>
void check_every_isa(const LayoutScene& scene, Intersect&& intersect, Occluded&& occluded) {
  const std::span<const Ray> rays(scene.rays);
  std::vector<Hit> reference(scene.rays.size());
  std::vector<uint8_t> blocked(scene.rays.size());
  intersect(Isa::scalar, rays, std::span<Hit>(reference));
  occluded(Isa::scalar, rays, std::span<uint8_t>(blocked));
  for (size_t i = 0; i < scene.rays.size(); ++i) {
    const Hit oracle = brute_force_intersect(scene.mesh, scene.rays[i]);
    CHECK_MESSAGE(compare_hits(scene.mesh, scene.rays[i], reference[i], oracle) == "", i);
    CHECK(bool(blocked[i]) == reference[i].found());  // one kernel, one decision
  }
  for (const Isa isa : supported_isas()) {
    CAPTURE(isa_name(isa));
    std::vector<Hit> hits(scene.rays.size());
    std::vector<uint8_t> isa_blocked(scene.rays.size());
    intersect(isa, rays, std::span<Hit>(hits));
    occluded(isa, rays, std::span<uint8_t>(isa_blocked));
    int differ = 0;
    for (size_t i = 0; i < hits.size(); ++i)
      differ += !same_bits(hits[i], reference[i]) || isa_blocked[i] != blocked[i];
    CHECK(differ == 0);
  }
}

}  // namespace rtk::test
