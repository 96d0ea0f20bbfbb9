// What chapters 4 and 5 check every tree with: traced by the kernels of chapters 2 and 3 on
// every ISA, the answers against the brute-force oracle.
#pragma once

#include <doctest/doctest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "01_base/cpu_features.h"
#include "testing/brute_force.h"

namespace rtk::test {

/// Traces `rays` through `bvh` with every ISA and counts disagreements with the oracle: every
/// hit within the oracle's tolerance, and occlusion agreeing with the hit or with the oracle.
/// With `same_as`, an answer outside the tolerance still passes if it is bit for bit the answer
/// of `same_as` on the same ISA (Möller-Trumbore rounds differently from the double-precision
/// oracle on a few grazing rays through slivers, whatever the tree).
template <class Bvh>
void check_against_oracle(const Bvh& bvh, const TriangleMesh& mesh, const std::vector<Ray>& rays,
                          const Bvh* same_as = nullptr) {
  std::vector<Hit> oracle(rays.size());
  std::vector<uint8_t> oracle_occluded(rays.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    oracle[i] = brute_force_intersect(mesh, rays[i]);
    oracle_occluded[i] = brute_force_occluded(mesh, rays[i]) ? 1 : 0;
  }
  for (const Isa isa : supported_isas()) {
    CAPTURE(std::string(isa_name(isa)));
    std::vector<Hit> hits(rays.size()), reference(rays.size());
    std::vector<uint8_t> blocked(rays.size());
    intersect(isa, bvh, rays, hits);
    occluded(isa, bvh, rays, blocked);
    if (same_as) intersect(isa, *same_as, rays, reference);
    int wrong_hits = 0, wrong_occlusion = 0;
    std::string first;
    for (size_t i = 0; i < rays.size(); ++i) {
      std::string why = compare_hits(mesh, rays[i], hits[i], oracle[i]);
      if (!why.empty() && same_as && hits[i].prim == reference[i].prim && hits[i].t == reference[i].t) why.clear();
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

}  // namespace rtk::test
