// Chapter 6's kernels: every layout in a BVH of width N = RTK_WIDTH, tested with
// Möller-Trumbore. Compiled once per ISA and per width (cmake/rtk_isa.cmake).
#include "02_bvh2/leaf_intersector.h"
#include "03_bvh4/bvhn_traverser.h"
#include "06_layouts/layout_bvh.h"
#include "06_layouts/layout_loads.h"

namespace rtk::RTK_ISA {

// [ch06-kernels]
template <int N>
TraceKernels layout_kernels(TriangleLayout layout) {
  // One traversal instantiation per layout: the precomputed blocks give Möller-Trumbore its
  // edges and normal, the others their vertices.
  using M = MoellerTrumbore;
  switch (layout) {
    case TriangleLayout::triangle1: return bvhn_batch_kernels<N, LeafIntersector<Triangle1Layout, M, true>>();
    case TriangleLayout::triangle4: return bvhn_batch_kernels<N, LeafIntersector<Triangle4Layout, M, true>>();
    case TriangleLayout::triangle8: return bvhn_batch_kernels<N, LeafIntersector<Triangle8Layout, M, true>>();
    case TriangleLayout::triangle1i: return bvhn_batch_kernels<N, LeafIntersector<Triangle1iLayout, M>>();
    case TriangleLayout::triangle4i: return bvhn_batch_kernels<N, LeafIntersector<Triangle4iLayout, M>>();
    case TriangleLayout::triangle1v: return bvhn_batch_kernels<N, LeafIntersector<Triangle1vLayout, M>>();
    case TriangleLayout::triangle4v: return bvhn_batch_kernels<N, LeafIntersector<Triangle4vLayout, M>>();
  }
  return {};
}
// [ch06-kernels]

template TraceKernels layout_kernels<RTK_WIDTH>(TriangleLayout);

}  // namespace rtk::RTK_ISA
