// The BVH8 kernels of one ISA: this file is compiled once per ISA (cmake/rtk_isa.cmake).
#include "02_bvh2/triangle1_intersector.h"
#include "03_bvh4/bvhn_traverser.h"

namespace rtk::RTK_ISA {

using Bvh8Kernels = BvhNKernels<8, Triangle1Intersector>;

void intersect_bvh8(const BVH8& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  require_same_size(rays.size(), hits.size());
  require_layout(bvh.leaves, Triangle1Intersector::kLayout);
  intersect_rays<8, Triangle1Intersector, Tricks{}, false>(bvh, rays, hits, nullptr);
}

void occluded_bvh8(const BVH8& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  require_same_size(rays.size(), occluded.size());
  require_layout(bvh.leaves, Triangle1Intersector::kLayout);
  occluded_rays<8, Triangle1Intersector, Tricks{}, false>(bvh, rays, occluded, nullptr);
}

void intersect_bvh8_tricks(const BVH8& bvh, const Tricks& tricks, std::span<const Ray> rays,
                           std::span<Hit> hits, TraversalStats* stats) {
  Bvh8Kernels::intersect(bvh, tricks, rays, hits, stats);
}

void occluded_bvh8_tricks(const BVH8& bvh, const Tricks& tricks, std::span<const Ray> rays,
                          std::span<uint8_t> occluded, TraversalStats* stats) {
  Bvh8Kernels::occluded(bvh, tricks, rays, occluded, stats);
}

}  // namespace rtk::RTK_ISA
