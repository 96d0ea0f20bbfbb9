/// \file
/// The run-time choice of leaf policy for a LayoutBVH: one traversal instantiation per
/// layout and intersector, all tricks of chapter 3 on. Per-ISA template.
#pragma once

#ifndef RTK_ISA
#error "layout_traversal.h belongs to kernel sources compiled once per ISA"
#endif

#include <span>
#include <stdexcept>

#include "03_bvh4/bvhn_traverser.h"
#include "06_layouts/layout_bvh.h"
#include "06_layouts/leaf_intersectors.h"

namespace rtk::RTK_ISA {

/// Calls `f.template operator()<Leaf>()` with the leaf policy of `config`.
template <class F>
void with_leaf_policy(const TriangleConfig& config, F&& f) {
  using M = MoellerTrumbore;
  using P = PlueckerStable;
  using W = Watertight;
  // The vertex layouts take any intersector.
  auto any_intersector = [&]<class L>() {
    switch (config.intersector) {
      case IntersectorKind::moeller: return f.template operator()<LeafIntersector<L, M>>();
      case IntersectorKind::pluecker: return f.template operator()<LeafIntersector<L, P>>();
      case IntersectorKind::watertight: return f.template operator()<LeafIntersector<L, W>>();
    }
  };
  if (!layout_supports(config.layout, config.intersector))
    throw std::invalid_argument("-tri: " + config.name() + " is not a supported configuration");
  switch (config.layout) {
    case TriangleLayout::triangle1: return f.template operator()<LeafIntersector<Triangle1Layout, M, true>>();
    case TriangleLayout::triangle4: return f.template operator()<LeafIntersector<Triangle4Layout, M, true>>();
    case TriangleLayout::triangle8: return f.template operator()<LeafIntersector<Triangle8Layout, M, true>>();
    case TriangleLayout::triangle1v: return any_intersector.template operator()<Triangle1vLayout>();
    case TriangleLayout::triangle4v: return any_intersector.template operator()<Triangle4vLayout>();
    case TriangleLayout::triangle1i: return any_intersector.template operator()<Triangle1iLayout>();
    case TriangleLayout::triangle4i: return any_intersector.template operator()<Triangle4iLayout>();
  }
}

/// Closest hits of rays[i] into hits[i] through a LayoutBVH.
template <int N>
void intersect_layout(const LayoutBVH<N>& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  require_same_size(rays.size(), hits.size());
  with_leaf_policy(bvh.config, [&]<class Leaf>() {
    require_layout(bvh.bvh.leaves, Leaf::kLayout);
    intersect_rays<N, Leaf, Tricks{}, false>(bvh.bvh, rays, hits, nullptr);
  });
}

/// Occlusion of rays[i] into occluded[i] through a LayoutBVH.
template <int N>
void occluded_layout(const LayoutBVH<N>& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  require_same_size(rays.size(), occluded.size());
  with_leaf_policy(bvh.config, [&]<class Leaf>() {
    require_layout(bvh.bvh.leaves, Leaf::kLayout);
    occluded_rays<N, Leaf, Tricks{}, false>(bvh.bvh, rays, occluded, nullptr);
  });
}

}  // namespace rtk::RTK_ISA
