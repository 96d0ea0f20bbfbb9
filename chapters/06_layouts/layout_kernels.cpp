// Chapter 6's kernels: every layout in a BVH of width N = RTK_WIDTH (2, 4 or 8), tested with
// Möller-Trumbore. Compiled once per ISA and per width (cmake/rtk_isa.cmake).
#include "02_bvh2/leaf_intersector.h"
#include "06_layouts/layout_bvh.h"
#include "06_layouts/layout_loads.h"
#include "06_layouts/layout_traversal.h"

namespace rtk::RTK_ISA {

// [ch06-kernels]
template <int N>
TraceKernels layout_kernels(TriangleLayout layout) {
  // One traversal instantiation per layout: the precomputed blocks give Möller-Trumbore its
  // edges and normal, the others their vertices.
  using M = MoellerTrumbore;
  switch (layout) {
    case TriangleLayout::triangle1: return layout_batch_kernels<N, LeafIntersector<Triangle1Layout, M, true>>();
    case TriangleLayout::triangle4: return layout_batch_kernels<N, LeafIntersector<Triangle4Layout, M, true>>();
    case TriangleLayout::triangle8: return layout_batch_kernels<N, LeafIntersector<Triangle8Layout, M, true>>();
    case TriangleLayout::triangle1i: return layout_batch_kernels<N, LeafIntersector<Triangle1iLayout, M>>();
    case TriangleLayout::triangle4i: return layout_batch_kernels<N, LeafIntersector<Triangle4iLayout, M>>();
    case TriangleLayout::triangle1v: return layout_batch_kernels<N, LeafIntersector<Triangle1vLayout, M>>();
    case TriangleLayout::triangle4v: return layout_batch_kernels<N, LeafIntersector<Triangle4vLayout, M>>();
  }
  return {};
}
// [ch06-kernels]

template TraceKernels layout_kernels<RTK_WIDTH>(TriangleLayout);

}  // namespace rtk::RTK_ISA
