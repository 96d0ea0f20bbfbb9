// This chapter's tests in chapter 6's layout BVHs of width N = RTK_WIDTH (2, 4 or 8). Compiled
// once per ISA and per width (cmake/rtk_isa.cmake).
#include <stdexcept>

#include "02_bvh2/leaf_intersector.h"
#include "06_layouts/layout_loads.h"
#include "06_layouts/layout_traversal.h"
#include "07_intersectors/layout_intersectors.h"
#include "07_intersectors/pluecker.h"
#include "07_intersectors/watertight.h"

namespace rtk::RTK_ISA {

namespace {

// The vertex and indexed layouts with the test T: chapter 2's leaf template, chapter 6's loaders.
template <int N, class T>
TraceKernels vertex_layout_kernels(TriangleLayout layout) {
  switch (layout) {
    case TriangleLayout::triangle1i: return layout_batch_kernels<N, LeafIntersector<Triangle1iLayout, T>>();
    case TriangleLayout::triangle4i: return layout_batch_kernels<N, LeafIntersector<Triangle4iLayout, T>>();
    case TriangleLayout::triangle1v: return layout_batch_kernels<N, LeafIntersector<Triangle1vLayout, T>>();
    case TriangleLayout::triangle4v: return layout_batch_kernels<N, LeafIntersector<Triangle4vLayout, T>>();
    default: break;
  }
  return {};
}

}  // namespace

template <int N>
TraceKernels intersector_kernels(TriangleConfig config) {
  if (!layout_supports(config.layout, config.intersector))
    throw std::invalid_argument("-tri: " + config.name() + " is not a supported configuration");
  switch (config.intersector) {
    case IntersectorKind::moeller: return layout_kernels<N>(config.layout);
    case IntersectorKind::pluecker: return vertex_layout_kernels<N, PlueckerStable>(config.layout);
    case IntersectorKind::watertight: return vertex_layout_kernels<N, Watertight>(config.layout);
  }
  return {};
}

template TraceKernels intersector_kernels<RTK_WIDTH>(TriangleConfig);

}  // namespace rtk::RTK_ISA
