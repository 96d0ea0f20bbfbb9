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
/// Traces a batch P rays at a time: the valid rays of each group of P consecutive ones form a
/// packet when there are at least two and they share an octant; otherwise the group is traced
/// one ray at a time by chapter 3's kernel with the same leaves, whose answers the packet's
/// equal. Invalid rays miss, as everywhere.
template <int N, int M, bool kOcclusion, class Answer>
void trace_in_packets(const void* structure, std::span<const Ray> rays, std::span<Answer> answers) {
  require_same_size(rays.size(), answers.size());
  using Leaf = LeafIntersector<TriangleMLayout<M>, MoellerTrumbore, true>;
  constexpr int P = kPacketWidth;
  const auto& bvh = *static_cast<const BVHN<N>*>(structure);
  for (size_t first = 0; first < rays.size(); first += P) {
    const size_t n = std::min<size_t>(P, rays.size() - first);
    Ray lanes[P];
    uint32_t index[P];
    int count = 0;
    uint32_t octants = 0;  // the octants seen, one bit each
    for (size_t i = first; i < first + n; ++i) {
      const bool valid = is_valid(rays[i]);
      octants |= valid ? 1u << octant_of(rays[i].dir) : 0u;
      count += valid;
    }
    const std::span<const Ray> group = rays.subspan(first, n);
    const std::span<Answer> out = answers.subspan(first, n);
    if (count < 2 || (octants & (octants - 1)) != 0) {
      if constexpr (kOcclusion) occluded_rays<N, Leaf, Tricks{}, false>(bvh, group, out, nullptr);
      else intersect_rays<N, Leaf, Tricks{}, false>(bvh, group, out, nullptr);
      continue;
    }
    count = 0;
    for (size_t i = first; i < first + n; ++i)
      if (is_valid(rays[i])) lanes[count] = rays[i], index[count++] = uint32_t(i);
    for (Answer& a : out) a = Answer{};  // invalid rays miss
    RayPacket<P> packet = make_packet<P, N>(lanes, count, uint32_t(std::countr_zero(octants)));
    Hit hits[P];
    uint8_t blocked[P] = {};
    trace_packet<P, N, M, kOcclusion>(bvh, lanes, packet, hits, blocked);
    for (int k = 0; k < count; ++k) {
      if constexpr (kOcclusion) answers[index[k]] = blocked[k];
      else answers[index[k]] = hits[k];
    }
  }
}
// [ch09-packet-batch]

template <int N, int M>
constexpr TraceKernels packet_batch_kernels() {
  return {&trace_in_packets<N, M, false, Hit>, &trace_in_packets<N, M, true, uint8_t>};
}

}  // namespace

template <int N>
TraceKernels packet_kernels(TriangleConfig tri) {
  if (kPacketWidth < 4 || tri.intersector != IntersectorKind::moeller) return {};
  if (tri.layout == TriangleLayout::triangle8) return packet_batch_kernels<N, 8>();
  if (tri.layout == TriangleLayout::triangle4) return packet_batch_kernels<N, 4>();
  return {};
}

template TraceKernels packet_kernels<RTK_WIDTH>(TriangleConfig);

}  // namespace rtk::RTK_ISA
