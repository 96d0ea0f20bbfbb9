// The BVH2 kernels of one ISA: this file is compiled once per ISA (cmake/rtk_isa.cmake).
#include "02_bvh2/bvh2_traverser.h"
#include "02_bvh2/triangle1_intersector.h"

namespace rtk::RTK_ISA {

void intersect_bvh2(const BVH2& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  require_same_size(rays.size(), hits.size());
  require_layout(bvh.leaves, Triangle1Intersector::kLayout);
  for (size_t i = 0; i < rays.size(); ++i) {
    Hit hit;
    trace_bvh2<Triangle1Intersector, false>(bvh, rays[i], hit);
    hits[i] = hit;
  }
}

void occluded_bvh2(const BVH2& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  require_same_size(rays.size(), occluded.size());
  require_layout(bvh.leaves, Triangle1Intersector::kLayout);
  Hit unused;
  for (size_t i = 0; i < rays.size(); ++i)
    occluded[i] = trace_bvh2<Triangle1Intersector, true>(bvh, rays[i], unused) ? 1 : 0;
}

}  // namespace rtk::RTK_ISA
