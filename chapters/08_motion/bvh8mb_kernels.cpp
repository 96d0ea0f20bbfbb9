// The BVH8MB kernels of one ISA, compiled once per ISA: eight children per node, for the
// measurement of whether the wider node pays with AVX2 and AVX-512 (chapter.md).
#include "08_motion/bvhmb_traverser.h"

namespace rtk::RTK_ISA {

void intersect_bvh8mb(const BVH8MB& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  intersect_mb<8>(bvh, rays, hits);
}

void occluded_bvh8mb(const BVH8MB& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  occluded_mb<8>(bvh, rays, occluded);
}

}  // namespace rtk::RTK_ISA
