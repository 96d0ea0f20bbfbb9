/// \file
/// How the per-ISA copies of a kernel are declared and chosen at run time.
///
/// A kernel source (`*_kernels.cpp`) is compiled four times, each time inside
/// `namespace rtk::RTK_ISA` with that ISA's compiler flags. Code outside the kernels sees four
/// functions with the same name in four namespaces and picks one with the run-time ISA.
#pragma once

#include "01_base/cpu_features.h"

// [ch01-dispatch]
/// Declares the same entity once in each ISA's namespace (rtk::scalar, rtk::sse4, rtk::avx2,
/// rtk::avx512). Use it inside `namespace rtk`.
#define RTK_DECLARE_FOR_EACH_ISA(...)   \
  namespace scalar { __VA_ARGS__; }     \
  namespace sse4 { __VA_ARGS__; }       \
  namespace avx2 { __VA_ARGS__; }       \
  namespace avx512 { __VA_ARGS__; }

/// The entity `name` of the ISA `isa`, one of the four declared by RTK_DECLARE_FOR_EACH_ISA.
#define RTK_PICK_ISA(isa, name) \
  ::rtk::pick_isa((isa), &::rtk::scalar::name, &::rtk::sse4::name, &::rtk::avx2::name, \
                  &::rtk::avx512::name)

namespace rtk {

/// Returns the one of four per-ISA entities that belongs to `isa`.
template <class T>
T pick_isa(Isa isa, T scalar_entry, T sse4_entry, T avx2_entry, T avx512_entry) {
  switch (isa) {
    case Isa::sse4: return sse4_entry;
    case Isa::avx2: return avx2_entry;
    case Isa::avx512: return avx512_entry;
    case Isa::scalar: break;
  }
  return scalar_entry;
}
// [ch01-dispatch]

}  // namespace rtk
