/// \file
/// Rays in packets: batch kernels that trace P consecutive rays of a batch together, one per
/// SIMD lane (packet_traverser.h), where they share an octant, for the layout BVHs whose leaves
/// are precomputed triangles tested with Möller-Trumbore (triangle4, triangle8), the layouts of
/// RTK's defaults.
#pragma once

#include <span>

#include "01_base/isa_dispatch.h"
#include "02_bvh2/trace_kernels.h"
#include "06_layouts/layout_bvh.h"
#include "07_intersectors/triangle_config.h"

namespace rtk {

// [ch09-packet-kernels]
/// The packet kernels of each ISA for a layout BVH of width N (4 or 8) whose leaves are in
/// `tri.layout`, tested with `tri.intersector`: `structure` is the LayoutBVH's `bvh`. Every ray
/// gets the answer of chapter 7's intersector_kernels, bit for bit. Empty kernels (null
/// pointers) where there are none: other layouts and tests, and the scalar ISA, whose packet of
/// one ray would be the single ray.
RTK_DECLARE_FOR_EACH_ISA(template <int N> TraceKernels packet_kernels(TriangleConfig tri))
/// Rays in a packet on each ISA, the floats of its widest register: 4 (SSE4), 8 (AVX2), 16
/// (AVX-512), and 1 for the scalar ISA, which has no packets.
inline int packet_width(Isa isa) {
  switch (isa) {
    case Isa::sse4: return 4;
    case Isa::avx2: return 8;
    case Isa::avx512: return 16;
    default: return 1;
  }
}

/// Whether `isa` has packet kernels for `tri`.
inline bool has_packets(Isa isa, TriangleConfig tri) {
  return RTK_PICK_ISA(isa, packet_kernels<8>)(tri).intersect != nullptr;
}
/// Closest hits through a layout BVH of width N in packets, with the kernels of `isa` (which
/// must have them: has_packets).
template <int N>
void intersect_packets(Isa isa, const LayoutBVH<N>& bvh, IntersectorKind kind, std::span<const Ray> rays,
                       std::span<Hit> hits) {
  RTK_PICK_ISA(isa, packet_kernels<N>)({bvh.layout, kind}).intersect(&bvh.bvh, rays, hits);
}
/// Occlusion through a layout BVH of width N in packets.
template <int N>
void occluded_packets(Isa isa, const LayoutBVH<N>& bvh, IntersectorKind kind, std::span<const Ray> rays,
                      std::span<uint8_t> occluded) {
  RTK_PICK_ISA(isa, packet_kernels<N>)({bvh.layout, kind}).occluded(&bvh.bvh, rays, occluded);
}
// [ch09-packet-kernels]

}  // namespace rtk
