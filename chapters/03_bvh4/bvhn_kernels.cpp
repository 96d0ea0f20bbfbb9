// The BVHN kernels of one ISA and one node width: this file is compiled once per ISA and per
// width N = RTK_WIDTH (cmake/rtk_isa.cmake), with triangle1 leaves.
#include "02_bvh2/leaf_intersector.h"
#include "03_bvh4/bvhn_traverser.h"

namespace rtk::RTK_ISA {

template <int N>
TraceKernels bvhn_kernels() {
  return bvhn_batch_kernels<N, Triangle1Moeller>();
}

template <int N>
void intersect_bvhn_tricks(const BVHN<N>& bvh, const Tricks& tricks, std::span<const Ray> rays,
                           std::span<Hit> hits, TraversalStats* stats) {
  BvhNKernels<N, Triangle1Moeller>::intersect(bvh, tricks, rays, hits, stats);
}

template <int N>
void occluded_bvhn_tricks(const BVHN<N>& bvh, const Tricks& tricks, std::span<const Ray> rays,
                          std::span<uint8_t> occluded, TraversalStats* stats) {
  BvhNKernels<N, Triangle1Moeller>::occluded(bvh, tricks, rays, occluded, stats);
}

template TraceKernels bvhn_kernels<RTK_WIDTH>();
template void intersect_bvhn_tricks<RTK_WIDTH>(const BVHN<RTK_WIDTH>&, const Tricks&, std::span<const Ray>,
                                               std::span<Hit>, TraversalStats*);
template void occluded_bvhn_tricks<RTK_WIDTH>(const BVHN<RTK_WIDTH>&, const Tricks&, std::span<const Ray>,
                                              std::span<uint8_t>, TraversalStats*);

}  // namespace rtk::RTK_ISA
