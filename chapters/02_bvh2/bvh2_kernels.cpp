// The BVH2 kernels of one ISA: this file is compiled once per ISA (cmake/rtk_isa.cmake).
#include "02_bvh2/bvh2_traverser.h"
#include "02_bvh2/leaf_intersector.h"

namespace rtk::RTK_ISA {

TraceKernels bvh2_kernels() { return bvh2_batch_kernels<Triangle1Moeller>(); }

}  // namespace rtk::RTK_ISA
