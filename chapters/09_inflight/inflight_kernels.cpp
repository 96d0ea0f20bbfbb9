// Chapter 9's kernels: rays in flight through a layout BVH of width N = RTK_WIDTH, with every
// leaf layout and intersector of chapters 6 and 7. Compiled once per ISA and per width
// (cmake/rtk_isa.cmake).
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "07_intersectors/leaf_intersectors.h"
#include "09_inflight/inflight_traverser.h"

namespace rtk::RTK_ISA {

namespace {

// The kernels of one leaf intersector with the configuration `config`, if it is compiled: every
// configuration of kInflightConfigs for the ablation's leaves, kDefaultInflight for the others.
template <int N, class Leaf, bool kAblation, size_t... I>
TraceKernels pick_config(InflightConfig config, std::index_sequence<I...>) {
  TraceKernels out{};
  if constexpr (kAblation) {
    ((config == kInflightConfigs[I]
          ? void(out = inflight_batch_kernels<N, Leaf, kInflightConfigs[I].rays, kInflightConfigs[I].prefetch>())
          : void()),
     ...);
  } else if (config == kDefaultInflight) {
    out = inflight_batch_kernels<N, Leaf, kDefaultInflight.rays, kDefaultInflight.prefetch>();
  }
  return out;
}

template <int N, class Leaf, bool kAblation = false>
TraceKernels kernels_of(InflightConfig config) {
  return pick_config<N, Leaf, kAblation>(config, std::make_index_sequence<kInflightConfigCount>{});
}

}  // namespace

template <int N>
TraceKernels inflight_kernels(TriangleConfig tri, InflightConfig config) {
  if (!layout_supports(tri.layout, tri.intersector))
    throw std::invalid_argument("-tri: " + tri.name() + " is not a supported configuration");
  const TraceKernels out = with_leaf_intersector(tri, [&](auto leaf) {
    using Leaf = typename decltype(leaf)::type;
    // The ablation's leaves: the precomputed blocks of four and eight with Möller-Trumbore.
    constexpr bool kAblation = std::is_same_v<Leaf, LeafIntersector<Triangle4Layout, MoellerTrumbore, true>> ||
                               std::is_same_v<Leaf, LeafIntersector<Triangle8Layout, MoellerTrumbore, true>>;
    return kernels_of<N, Leaf, kAblation>(config);
  });
  if (!out.intersect)
    throw std::invalid_argument("rays in flight: " + config.name() + " is not compiled for " + tri.name() +
                                " (every configuration is, for triangle4 and triangle8 with moeller; the others have " +
                                kDefaultInflight.name() + ")");
  return out;
}

template TraceKernels inflight_kernels<RTK_WIDTH>(TriangleConfig, InflightConfig);

}  // namespace rtk::RTK_ISA
