// The BVH2 kernels of one ISA: this file is compiled once per ISA (cmake/rtk_isa.cmake).
#include "02_bvh2/bvh2_traverser.h"
#include "02_bvh2/leaf_intersector.h"

namespace rtk::RTK_ISA {

namespace {

void intersect_bvh2(const void* structure, std::span<const Ray> rays, std::span<Hit> hits) {
  require_same_size(rays.size(), hits.size());
  const BVH2& bvh = *static_cast<const BVH2*>(structure);
  for (size_t i = 0; i < rays.size(); ++i) {
    Hit hit;
    trace_bvh2<Triangle1Moeller, false>(bvh, rays[i], hit);
    hits[i] = hit;
  }
}

void occluded_bvh2(const void* structure, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  require_same_size(rays.size(), occluded.size());
  const BVH2& bvh = *static_cast<const BVH2*>(structure);
  Hit unused;
  for (size_t i = 0; i < rays.size(); ++i)
    occluded[i] = trace_bvh2<Triangle1Moeller, true>(bvh, rays[i], unused) ? 1 : 0;
}

}  // namespace

TraceKernels bvh2_kernels() { return {&intersect_bvh2, &occluded_bvh2}; }

}  // namespace rtk::RTK_ISA
