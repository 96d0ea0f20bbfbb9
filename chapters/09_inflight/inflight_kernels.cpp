// Chapter 9's kernels: rays in flight through a layout BVH of width N = RTK_WIDTH, with every
// leaf layout and intersector of chapters 6 and 7. Compiled once per ISA and per width
// (cmake/rtk_isa.cmake).
#include <stdexcept>
#include <utility>

#include "02_bvh2/leaf_intersector.h"
#include "06_layouts/layout_loads.h"
#include "07_intersectors/pluecker.h"
#include "07_intersectors/watertight.h"
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

// The vertex and indexed layouts with the test T.
template <int N, class T>
TraceKernels vertex_layout_kernels(TriangleLayout layout, InflightConfig config) {
  switch (layout) {
    case TriangleLayout::triangle1i: return kernels_of<N, LeafIntersector<Triangle1iLayout, T>>(config);
    case TriangleLayout::triangle4i: return kernels_of<N, LeafIntersector<Triangle4iLayout, T>>(config);
    case TriangleLayout::triangle1v: return kernels_of<N, LeafIntersector<Triangle1vLayout, T>>(config);
    case TriangleLayout::triangle4v: return kernels_of<N, LeafIntersector<Triangle4vLayout, T>>(config);
    default: break;
  }
  return {};
}

template <int N>
TraceKernels moeller_kernels(TriangleLayout layout, InflightConfig config) {
  using M = MoellerTrumbore;
  switch (layout) {
    case TriangleLayout::triangle1: return kernels_of<N, LeafIntersector<Triangle1Layout, M, true>>(config);
    case TriangleLayout::triangle4: return kernels_of<N, LeafIntersector<Triangle4Layout, M, true>, true>(config);
    case TriangleLayout::triangle8: return kernels_of<N, LeafIntersector<Triangle8Layout, M, true>, true>(config);
    default: return vertex_layout_kernels<N, M>(layout, config);
  }
}

}  // namespace

template <int N>
TraceKernels inflight_kernels(TriangleConfig tri, InflightConfig config) {
  if (!layout_supports(tri.layout, tri.intersector))
    throw std::invalid_argument("-tri: " + tri.name() + " is not a supported configuration");
  TraceKernels out{};
  switch (tri.intersector) {
    case IntersectorKind::moeller: out = moeller_kernels<N>(tri.layout, config); break;
    case IntersectorKind::pluecker: out = vertex_layout_kernels<N, PlueckerStable>(tri.layout, config); break;
    case IntersectorKind::watertight: out = vertex_layout_kernels<N, Watertight>(tri.layout, config); break;
  }
  if (!out.intersect)
    throw std::invalid_argument("rays in flight: " + config.name() + " is not compiled for " + tri.name() +
                                " (every configuration is, for triangle4 and triangle8 with moeller; the others have " +
                                kDefaultInflight.name() + ")");
  return out;
}

template TraceKernels inflight_kernels<RTK_WIDTH>(TriangleConfig, InflightConfig);

}  // namespace rtk::RTK_ISA
