// This chapter's tests in chapter 6's layout BVHs of width N = RTK_WIDTH (2, 4 or 8). Compiled
// once per ISA and per width (cmake/rtk_isa.cmake).
#include <stdexcept>

#include "06_layouts/layout_traversal.h"
#include "07_intersectors/layout_intersectors.h"
#include "07_intersectors/leaf_intersectors.h"

namespace rtk::RTK_ISA {

template <int N>
TraceKernels intersector_kernels(TriangleConfig config) {
  if (!layout_supports(config.layout, config.intersector))
    throw std::invalid_argument("-tri: " + config.name() + " is not a supported configuration");
  return with_leaf_intersector(config, [](auto leaf) {
    return layout_batch_kernels<N, typename decltype(leaf)::type>();
  });
}

template TraceKernels intersector_kernels<RTK_WIDTH>(TriangleConfig);

}  // namespace rtk::RTK_ISA
