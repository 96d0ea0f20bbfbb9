// The BVH4 kernels of one ISA: this file is compiled once per ISA (cmake/rtk_isa.cmake).
#include "02_bvh2/triangle1_intersector.h"
#include "03_bvh4/bvhn_traverser.h"

namespace rtk::RTK_ISA {

using Bvh4Kernels = BvhNKernels<4, Triangle1Intersector>;

void intersect_bvh4(const BVH4& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  require_same_size(rays.size(), hits.size());
  require_layout(bvh.leaves, Triangle1Intersector::kLayout);
  intersect_rays<4, Triangle1Intersector, Tricks{}, false>(bvh, rays, hits, nullptr);
}

void occluded_bvh4(const BVH4& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  require_same_size(rays.size(), occluded.size());
  require_layout(bvh.leaves, Triangle1Intersector::kLayout);
  occluded_rays<4, Triangle1Intersector, Tricks{}, false>(bvh, rays, occluded, nullptr);
}

void intersect_bvh4_tricks(const BVH4& bvh, const Tricks& tricks, std::span<const Ray> rays,
                           std::span<Hit> hits, TraversalStats* stats) {
  Bvh4Kernels::intersect(bvh, tricks, rays, hits, stats);
}

void occluded_bvh4_tricks(const BVH4& bvh, const Tricks& tricks, std::span<const Ray> rays,
                          std::span<uint8_t> occluded, TraversalStats* stats) {
  Bvh4Kernels::occluded(bvh, tricks, rays, occluded, stats);
}

}  // namespace rtk::RTK_ISA
