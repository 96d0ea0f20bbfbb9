// Chapter 6's BVH4 kernels for every layout and intersector, compiled once per ISA.
#include "06_layouts/layout_traversal.h"

namespace rtk::RTK_ISA {

void intersect_layout_bvh4(const LayoutBVH<4>& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  intersect_layout<4>(bvh, rays, hits);
}

void occluded_layout_bvh4(const LayoutBVH<4>& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  occluded_layout<4>(bvh, rays, occluded);
}

}  // namespace rtk::RTK_ISA
