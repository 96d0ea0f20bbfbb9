// The BVH4MB kernels of one ISA: this file is compiled once per ISA (cmake/rtk_isa.cmake).
#include "08_motion/bvhmb_traverser.h"

namespace rtk::RTK_ISA {

void intersect_bvh4mb(const BVH4MB& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  intersect_mb<4>(bvh, rays, hits);
}

void occluded_bvh4mb(const BVH4MB& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  occluded_mb<4>(bvh, rays, occluded);
}

}  // namespace rtk::RTK_ISA
