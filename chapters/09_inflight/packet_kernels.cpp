// Chapter 9's packet kernels: a batch traced P rays at a time where P consecutive rays share an
// octant, one ray at a time (chapter 3's traversal) elsewhere, through a layout BVH of width
// N = RTK_WIDTH whose leaves are blocks of precomputed triangles (triangle4, triangle8) tested
// with Möller-Trumbore. Compiled once per ISA and per width (cmake/rtk_isa.cmake).
#include <algorithm>
#include <bit>
#include <cstdint>
#include <span>

#include "06_layouts/layout_bvh.h"
#include "07_intersectors/leaf_intersectors.h"
#include "09_inflight/packet_traverser.h"
#include "09_inflight/packets.h"

namespace rtk::RTK_ISA {

namespace {

// [ch09-packet-batch]
/// Traces a batch P rays at a time: a group of P consecutive rays of one octant forms a packet
/// of its valid rays when there are at least two; the other groups are traced one ray at a time
/// by chapter 3's kernel with the same leaves (a run of them in one call), whose answers the
/// packet's equal. Invalid rays miss, as everywhere.
template <int N, int M, bool kOcclusion, class Answer>
void trace_in_packets(const void* structure, std::span<const Ray> rays, std::span<Answer> answers) {
  require_same_size(rays.size(), answers.size());
  using Leaf = LeafIntersector<TriangleMLayout<M>, MoellerTrumbore, true>;
  constexpr int P = kPacketWidth;
  const auto& bvh = *static_cast<const BVHN<N>*>(structure);
  // Rays [single, first) wait to be traced one at a time, in one call.
  size_t single = 0;
  auto flush = [&](size_t end) {
    const std::span<const Ray> run = rays.subspan(single, end - single);
    const std::span<Answer> out = answers.subspan(single, end - single);
    if constexpr (kOcclusion) occluded_rays<N, Leaf, Tricks{}, false>(bvh, run, out, nullptr);
    else intersect_rays<N, Leaf, Tricks{}, false>(bvh, run, out, nullptr);
  };
  for (size_t first = 0; first < rays.size(); first += P) {
    const size_t n = std::min<size_t>(P, rays.size() - first);
    // One octant for all (incoherent rays differ within two or three, and the test stops
    // there), then at least two valid rays; anything else joins the single rays.
    const uint32_t octant = octant_of(rays[first].dir);
    size_t same = first + 1;
    while (same < first + n && octant_of(rays[same].dir) == octant) ++same;
    if (same < first + n) continue;
    Ray lanes[P];
    uint32_t index[P];
    int count = 0;
    for (size_t i = first; i < first + n; ++i)
      if (is_valid(rays[i])) lanes[count] = rays[i], index[count++] = uint32_t(i);
    if (count < 2) continue;
    flush(first);
    single = first + n;
    for (size_t i = first; i < first + n; ++i) answers[i] = Answer{};  // invalid rays miss
    RayPacket<P> packet = make_packet<P, N>(lanes, count, octant);
    Hit hits[P];
    uint8_t blocked[P] = {};
    trace_packet<P, N, M, kOcclusion>(bvh, lanes, packet, hits, blocked);
    for (int k = 0; k < count; ++k) {
      if constexpr (kOcclusion) answers[index[k]] = blocked[k];
      else answers[index[k]] = hits[k];
    }
  }
  flush(rays.size());
}
// [ch09-packet-batch]

template <int N, int M>
constexpr TraceKernels packet_batch_kernels() {
  return {&trace_in_packets<N, M, false, Hit>, &trace_in_packets<N, M, true, uint8_t>};
}

}  // namespace

template <int N>
TraceKernels packet_kernels(TriangleConfig tri) {
  if constexpr (kPacketWidth < 4) {
    return {};  // the scalar ISA: a packet of one ray is the single ray
  } else {
    if (tri.intersector != IntersectorKind::moeller) return {};
    if (tri.layout == TriangleLayout::triangle8) return packet_batch_kernels<N, 8>();
    if (tri.layout == TriangleLayout::triangle4) return packet_batch_kernels<N, 4>();
    return {};
  }
}

template TraceKernels packet_kernels<RTK_WIDTH>(TriangleConfig);

}  // namespace rtk::RTK_ISA
