/// \file
/// The traversal of a layout BVH of any width: the one template the layout kernels of chapters
/// 6 and 7 are made with. Per-ISA template: include from kernel sources only.
#pragma once

#ifndef RTK_ISA
#error "layout_traversal.h belongs to kernel sources compiled once per ISA"
#endif

#include "02_bvh2/bvh2_traverser.h"
#include "03_bvh4/bvhn_traverser.h"
#include "06_layouts/layout_bvh.h"

namespace rtk::RTK_ISA {

// [ch06-layout-traversal]
/// The batch kernels of a LayoutTree<N> whose leaves Leaf reads: chapter 2's binary traversal
/// for N = 2, chapter 3's N-wide one for 4 and 8. Both are templates over the leaf intersector,
/// so a layout or a test added to one width is added to all of them.
template <int N, class Leaf>
constexpr TraceKernels layout_batch_kernels() {
  if constexpr (N == 2) return bvh2_batch_kernels<Leaf>();
  else return bvhn_batch_kernels<N, Leaf>();
}
// [ch06-layout-traversal]

}  // namespace rtk::RTK_ISA
