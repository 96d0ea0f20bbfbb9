// BVH4 kernels with chapter 2's exit widening switched off, for the leak chart only (see
// layout_intersectors.h). Compiled once per ISA.
#include "02_bvh2/leaf_intersector.h"
#include "03_bvh4/bvhn_traverser.h"
#include "06_layouts/layout_loads.h"
#include "07_intersectors/layout_intersectors.h"
#include "07_intersectors/pluecker.h"
#include "07_intersectors/watertight.h"

namespace rtk::RTK_ISA {

TraceKernels unwidened_bvh4_kernels(IntersectorKind kind) {
  constexpr Tricks kUnwidened{.conservative_exits = false};
  switch (kind) {
    case IntersectorKind::moeller:
      return bvhn_batch_kernels<4, LeafIntersector<Triangle4Layout, MoellerTrumbore, true>, kUnwidened>();
    case IntersectorKind::pluecker:
      return bvhn_batch_kernels<4, LeafIntersector<Triangle4vLayout, PlueckerStable>, kUnwidened>();
    case IntersectorKind::watertight:
      return bvhn_batch_kernels<4, LeafIntersector<Triangle4vLayout, Watertight>, kUnwidened>();
  }
  return {};
}

}  // namespace rtk::RTK_ISA
