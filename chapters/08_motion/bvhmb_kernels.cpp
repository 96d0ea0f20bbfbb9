// The motion-blur kernels of one ISA and one node width N = RTK_WIDTH: compiled once per ISA and
// per width (cmake/rtk_isa.cmake).
#include "08_motion/bvhmb_traverser.h"

namespace rtk::RTK_ISA {

namespace {

template <int N, MotionStorage S>
TraceKernels with_test(IntersectorKind intersector) {
  switch (intersector) {
    case IntersectorKind::moeller: return motion_batch_kernels<N, MotionLeaf<S, MoellerTrumbore>>();
    case IntersectorKind::pluecker: return motion_batch_kernels<N, MotionLeaf<S, PlueckerStable>>();
    case IntersectorKind::watertight: return motion_batch_kernels<N, MotionLeaf<S, Watertight>>();
  }
  return {};
}

}  // namespace

template <int N>
TraceKernels motion_kernels(MotionStorage storage, IntersectorKind intersector) {
  return storage == MotionStorage::sparse ? with_test<N, MotionStorage::sparse>(intersector)
                                          : with_test<N, MotionStorage::dense>(intersector);
}

template TraceKernels motion_kernels<RTK_WIDTH>(MotionStorage, IntersectorKind);

}  // namespace rtk::RTK_ISA
