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
  // One traversal instantiation per layout, with that layout's leaf policy.
  return with_moeller_leaf(layout, [](auto leaf) {
    return layout_batch_kernels<N, typename decltype(leaf)::type>();
  });
}
// [ch06-kernels]

template TraceKernels layout_kernels<RTK_WIDTH>(TriangleLayout);

}  // namespace rtk::RTK_ISA
