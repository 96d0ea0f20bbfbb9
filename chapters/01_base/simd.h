/// \file
/// The SIMD wrappers: vfloat<N>, vint<N> and vbool<N>, for kernels written once for any width.
///
/// Include this only from a kernel source compiled per ISA (RTK_ISA set by CMake). Every width
/// exists in every ISA: the portable backend (simd_portable.h) implements any N with plain
/// arrays, and each ISA replaces the widths its registers hold with intrinsics:
/// SSE4 vfloat<4>, AVX2 vfloat<8>, AVX-512 vfloat<16>. The portable backend is the
/// specification; the intrinsic backends are tested against it lane by lane.
#pragma once

#ifndef RTK_ISA
#error "simd.h belongs to kernel sources compiled once per ISA (see cmake/rtk_isa.cmake)"
#endif

#include "01_base/simd_portable.h"

#if defined(__SSE4_2__)
#include "01_base/simd_sse4.h"
#endif
#if defined(__AVX2__)
#include "01_base/simd_avx2.h"
#endif
#if defined(__AVX512F__)
#include "01_base/simd_avx512.h"
#endif

namespace rtk::RTK_ISA {

/// The widest float vector this ISA holds in one register (1 for the scalar variant).
#if defined(__AVX512F__)
inline constexpr int kNativeWidth = 16;
#elif defined(__AVX2__)
inline constexpr int kNativeWidth = 8;
#elif defined(__SSE4_2__)
inline constexpr int kNativeWidth = 4;
#else
inline constexpr int kNativeWidth = 1;
#endif

}  // namespace rtk::RTK_ISA
