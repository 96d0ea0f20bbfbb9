// Helpers shared by chapter 7's tests: run an intersector over all triangles with a chosen ISA
// and width, and count what matters.
#pragma once

#include <span>
#include <vector>

#include "01_base/cpu_features.h"
#include "07_intersectors/intersect_all.h"
#include "testing/brute_force.h"  // same_bits

namespace rtk::test {

/// Closest hits of `rays` among all `triangles` with one intersector, ISA and width.
inline std::vector<Hit> trace_all(const TriangleSoA& triangles, IntersectorKind kind, Isa isa,
                                  int width, std::span<const Ray> rays) {
  std::vector<Hit> hits(rays.size());
  RTK_PICK_ISA(isa, intersect_all)(triangles, kind, width, rays, hits);
  return hits;
}

}  // namespace rtk::test
