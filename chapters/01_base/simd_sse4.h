/// \file
/// The SSE4 backend: vbool<4>, vint<4> and vfloat<4>, one 128-bit register each.
///
/// Every operation of simd_portable.h has an exact-match overload here, with the portable
/// semantics (see that file's header comment). The same header serves the AVX2 and AVX-512
/// variants for their four-lane vectors; there the compiler may use what those ISAs add: FMA for
/// the fmadd family, vgatherdps for gather, and rcp14ps (error below 2^-14) for rcp_fast.
#pragma once

#ifndef RTK_ISA
#error "simd_sse4.h belongs to kernel sources compiled once per ISA (see cmake/rtk_isa.cmake)"
#endif
#if !defined(__SSE4_2__)
#error "simd_sse4.h needs SSE4.2 (-msse4.2)"
#endif

// GCC 12's AVX-512 intrinsics start many results from _mm512_undefined_*(), which
// -Wmaybe-uninitialized reports once inlined; the reports point into this header, so they are
// silenced for it alone.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop

#include "01_base/simd_portable.h"

namespace rtk::RTK_ISA {

// [ch01-sse4-vbool]
/// Four lanes of mask: a lane is all ones (true) or all zeros (false), as compares produce.
template <>
struct vbool<4> {
  static constexpr int size = 4;
  __m128 m;

  vbool() = default;
  vbool(__m128 mask) : m(mask) {}
  /// All lanes set to `b`.
  vbool(bool b) : m(_mm_castsi128_ps(_mm_set1_epi32(b ? -1 : 0))) {}
  /// The lanes whose bit is set in `bits` (bit i is lane i).
  static vbool from_bits(uint32_t bits) {
    const __m128i lane_bit = _mm_setr_epi32(1, 2, 4, 8);
    const __m128i masked = _mm_and_si128(_mm_set1_epi32(int32_t(bits)), lane_bit);
    return _mm_castsi128_ps(_mm_cmpeq_epi32(masked, lane_bit));
  }
  bool operator[](int i) const { return (_mm_movemask_ps(m) >> i) & 1; }
};
// [ch01-sse4-vbool]

RTK_INLINE vbool<4> operator&(vbool<4> a, vbool<4> b) { return _mm_and_ps(a.m, b.m); }
RTK_INLINE vbool<4> operator|(vbool<4> a, vbool<4> b) { return _mm_or_ps(a.m, b.m); }
RTK_INLINE vbool<4> operator^(vbool<4> a, vbool<4> b) { return _mm_xor_ps(a.m, b.m); }
RTK_INLINE vbool<4> operator!(vbool<4> a) { return _mm_xor_ps(a.m, vbool<4>(true).m); }
/// Lane i of the mask becomes bit i of the result (movmskps).
RTK_INLINE uint32_t movemask(vbool<4> a) { return uint32_t(_mm_movemask_ps(a.m)); }
RTK_INLINE bool any(vbool<4> a) { return movemask(a) != 0; }
RTK_INLINE bool all(vbool<4> a) { return movemask(a) == 0xF; }
RTK_INLINE bool none(vbool<4> a) { return movemask(a) == 0; }

/// Four 32-bit signed integers.
template <>
struct vint<4> {
  static constexpr int size = 4;
  __m128i m;

  vint() = default;
  vint(__m128i x) : m(x) {}
  vint(int32_t s) : m(_mm_set1_epi32(s)) {}
  static vint load(const int32_t* p) { return _mm_load_si128(reinterpret_cast<const __m128i*>(p)); }
  static vint loadu(const int32_t* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); }
  void store(int32_t* p) const { _mm_store_si128(reinterpret_cast<__m128i*>(p), m); }
  void storeu(int32_t* p) const { _mm_storeu_si128(reinterpret_cast<__m128i*>(p), m); }
  /// The lane indices 0, 1, 2, 3.
  static vint iota() { return _mm_setr_epi32(0, 1, 2, 3); }
  int32_t operator[](int i) const {
    alignas(16) int32_t lanes[4];
    store(lanes);
    return lanes[i];
  }
};

RTK_INLINE vint<4> operator+(vint<4> a, vint<4> b) { return _mm_add_epi32(a.m, b.m); }
RTK_INLINE vint<4> operator-(vint<4> a, vint<4> b) { return _mm_sub_epi32(a.m, b.m); }
RTK_INLINE vint<4> operator*(vint<4> a, vint<4> b) { return _mm_mullo_epi32(a.m, b.m); }
RTK_INLINE vint<4> operator&(vint<4> a, vint<4> b) { return _mm_and_si128(a.m, b.m); }
RTK_INLINE vint<4> operator|(vint<4> a, vint<4> b) { return _mm_or_si128(a.m, b.m); }
RTK_INLINE vint<4> operator^(vint<4> a, vint<4> b) { return _mm_xor_si128(a.m, b.m); }
// The count goes through a register (pslld xmm), so it need not be a compile-time constant.
RTK_INLINE vint<4> operator<<(vint<4> a, int n) { return _mm_sll_epi32(a.m, _mm_cvtsi32_si128(n)); }
RTK_INLINE vint<4> operator>>(vint<4> a, int n) { return _mm_sra_epi32(a.m, _mm_cvtsi32_si128(n)); }
RTK_INLINE vint<4> srl(vint<4> a, int n) { return _mm_srl_epi32(a.m, _mm_cvtsi32_si128(n)); }
RTK_INLINE vbool<4> operator==(vint<4> a, vint<4> b) { return _mm_castsi128_ps(_mm_cmpeq_epi32(a.m, b.m)); }
RTK_INLINE vbool<4> operator!=(vint<4> a, vint<4> b) { return !(a == b); }
RTK_INLINE vbool<4> operator<(vint<4> a, vint<4> b) { return _mm_castsi128_ps(_mm_cmplt_epi32(a.m, b.m)); }
RTK_INLINE vbool<4> operator>(vint<4> a, vint<4> b) { return _mm_castsi128_ps(_mm_cmpgt_epi32(a.m, b.m)); }
RTK_INLINE vint<4> min(vint<4> a, vint<4> b) { return _mm_min_epi32(a.m, b.m); }
RTK_INLINE vint<4> max(vint<4> a, vint<4> b) { return _mm_max_epi32(a.m, b.m); }
RTK_INLINE vint<4> select(vbool<4> m, vint<4> t, vint<4> f) {
  return _mm_castps_si128(_mm_blendv_ps(_mm_castsi128_ps(f.m), _mm_castsi128_ps(t.m), m.m));
}
// Integer reductions do not depend on the order; the halving order is simply the cheap one.
RTK_INLINE int32_t reduce_add(vint<4> a) {
  const __m128i h = _mm_add_epi32(a.m, _mm_unpackhi_epi64(a.m, a.m));
  return _mm_cvtsi128_si32(_mm_add_epi32(h, _mm_shuffle_epi32(h, 1)));
}
RTK_INLINE int32_t reduce_min(vint<4> a) {
  const __m128i h = _mm_min_epi32(a.m, _mm_unpackhi_epi64(a.m, a.m));
  return _mm_cvtsi128_si32(_mm_min_epi32(h, _mm_shuffle_epi32(h, 1)));
}
RTK_INLINE int32_t reduce_max(vint<4> a) {
  const __m128i h = _mm_max_epi32(a.m, _mm_unpackhi_epi64(a.m, a.m));
  return _mm_cvtsi128_si32(_mm_max_epi32(h, _mm_shuffle_epi32(h, 1)));
}

/// Four floats.
template <>
struct vfloat<4> {
  static constexpr int size = 4;
  __m128 m;

  vfloat() = default;
  vfloat(__m128 x) : m(x) {}
  /// All lanes set to `s` (a broadcast).
  vfloat(float s) : m(_mm_set1_ps(s)) {}
  static vfloat load(const float* p) { return _mm_load_ps(p); }
  static vfloat loadu(const float* p) { return _mm_loadu_ps(p); }
  void store(float* p) const { _mm_store_ps(p, m); }
  void storeu(float* p) const { _mm_storeu_ps(p, m); }
  /// Lane i is base[index[i]]: one vgatherdps with AVX2, four loads without.
  static vfloat gather(const float* base, vint<4> index) {
#if defined(__AVX2__)
    return _mm_i32gather_ps(base, index.m, 4);
#else
    return _mm_setr_ps(base[index[0]], base[index[1]], base[index[2]], base[index[3]]);
#endif
  }
  float operator[](int i) const {
    alignas(16) float lanes[4];
    store(lanes);
    return lanes[i];
  }
};

// The portable templates reach their lanes through `v`; these types have no `v`, so a portable
// loop can never be chosen for them without a compile error (see simd_portable.h).
static_assert(!portable_lanes<vfloat<4>> && !portable_lanes<vint<4>> && !portable_lanes<vbool<4>>);

RTK_INLINE vfloat<4> operator+(vfloat<4> a, vfloat<4> b) { return _mm_add_ps(a.m, b.m); }
RTK_INLINE vfloat<4> operator-(vfloat<4> a, vfloat<4> b) { return _mm_sub_ps(a.m, b.m); }
RTK_INLINE vfloat<4> operator*(vfloat<4> a, vfloat<4> b) { return _mm_mul_ps(a.m, b.m); }
RTK_INLINE vfloat<4> operator/(vfloat<4> a, vfloat<4> b) { return _mm_div_ps(a.m, b.m); }
RTK_INLINE vfloat<4>& operator+=(vfloat<4>& a, vfloat<4> b) { return a = a + b; }
RTK_INLINE vfloat<4>& operator-=(vfloat<4>& a, vfloat<4> b) { return a = a - b; }
RTK_INLINE vfloat<4>& operator*=(vfloat<4>& a, vfloat<4> b) { return a = a * b; }
RTK_INLINE vfloat<4>& operator/=(vfloat<4>& a, vfloat<4> b) { return a = a / b; }
RTK_INLINE vfloat<4> operator-(vfloat<4> a) { return _mm_xor_ps(a.m, _mm_set1_ps(-0.0f)); }

// [ch01-sse4-minmax]
/// minps and maxps are the portable rule in hardware: the second operand wins unless the
/// first is strictly smaller (larger), which is what a NaN or a pair of zeros needs.
RTK_INLINE vfloat<4> min(vfloat<4> a, vfloat<4> b) { return _mm_min_ps(a.m, b.m); }
RTK_INLINE vfloat<4> max(vfloat<4> a, vfloat<4> b) { return _mm_max_ps(a.m, b.m); }
// [ch01-sse4-minmax]

/// a * b + c and its sign variants: fused where the ISA has FMA, rounded twice where it has not.
#if defined(__FMA__)
RTK_INLINE vfloat<4> fmadd(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return _mm_fmadd_ps(a.m, b.m, c.m); }
RTK_INLINE vfloat<4> fmsub(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return _mm_fmsub_ps(a.m, b.m, c.m); }
RTK_INLINE vfloat<4> fnmadd(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return _mm_fnmadd_ps(a.m, b.m, c.m); }
RTK_INLINE vfloat<4> fnmsub(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return _mm_fnmsub_ps(a.m, b.m, c.m); }
#else
RTK_INLINE vfloat<4> fmadd(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return a * b + c; }
RTK_INLINE vfloat<4> fmsub(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return a * b - c; }
RTK_INLINE vfloat<4> fnmadd(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return c - a * b; }
RTK_INLINE vfloat<4> fnmsub(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return -(a * b) - c; }
#endif

RTK_INLINE vfloat<4> sqrt(vfloat<4> a) { return _mm_sqrt_ps(a.m); }
RTK_INLINE vfloat<4> floor(vfloat<4> a) { return _mm_round_ps(a.m, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC); }
RTK_INLINE vfloat<4> ceil(vfloat<4> a) { return _mm_round_ps(a.m, _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC); }

// [ch01-sse4-rcp]
/// The hardware estimate of 1/a (see the portable rcp_fast for its domain).
RTK_INLINE vfloat<4> rcp_fast(vfloat<4> a) {
#if defined(__AVX512VL__)
  return _mm_rcp14_ps(a.m);
#else
  return _mm_rcp_ps(a.m);
#endif
}
/// The estimate plus one Newton-Raphson step; where the step goes wrong (a = +-0 or +-inf, for
/// which the estimate is already exact, or a denormal, which rcpps reads as zero) the estimate
/// is kept.
RTK_INLINE vfloat<4> rcp(vfloat<4> a) {
  const vfloat<4> x = rcp_fast(a);
#if defined(__FMA__)
  const vfloat<4> refined = fmadd(x, fnmadd(a, x, vfloat<4>(1.0f)), x);
  return _mm_blendv_ps(refined.m, x.m, _mm_cmpunord_ps(refined.m, refined.m));
#else
  // Rounded step by step, x + x (1 - a x) would make the tiny correction x (1 - a x) a
  // denormal for large |a|, and denormal results are slow; x (2 - a x) keeps every
  // intermediate near 1 or near 1/a. Within the domain a x is near 1; it is NaN or inf
  // exactly where the estimate must stand.
  const vfloat<4> ax = a * x;
  const vfloat<4> refined = x * (vfloat<4>(2.0f) - ax);
  return _mm_blendv_ps(refined.m, x.m, _mm_cmpnle_ps(ax.m, _mm_set1_ps(2.0f)));
#endif
}
// [ch01-sse4-rcp]

RTK_INLINE vint<4> as_int(vfloat<4> a) { return _mm_castps_si128(a.m); }
RTK_INLINE vfloat<4> as_float(vint<4> a) { return _mm_castsi128_ps(a.m); }
RTK_INLINE vfloat<4> abs(vfloat<4> a) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), a.m); }
RTK_INLINE vfloat<4> signmask(vfloat<4> a) { return _mm_and_ps(_mm_set1_ps(-0.0f), a.m); }
RTK_INLINE vfloat<4> xorsign(vfloat<4> a, vfloat<4> b) { return _mm_xor_ps(a.m, signmask(b).m); }
RTK_INLINE vfloat<4> copysign(vfloat<4> a, vfloat<4> b) { return _mm_or_ps(abs(a).m, signmask(b).m); }
RTK_INLINE uint32_t sign_bits(vfloat<4> a) { return uint32_t(_mm_movemask_ps(a.m)); }

// [ch01-sse4-compare]
// Ordered predicates, false with a NaN; `!=` is the unordered one, true with a NaN.
RTK_INLINE vbool<4> operator<(vfloat<4> a, vfloat<4> b) { return _mm_cmplt_ps(a.m, b.m); }
RTK_INLINE vbool<4> operator<=(vfloat<4> a, vfloat<4> b) { return _mm_cmple_ps(a.m, b.m); }
RTK_INLINE vbool<4> operator>(vfloat<4> a, vfloat<4> b) { return _mm_cmpgt_ps(a.m, b.m); }
RTK_INLINE vbool<4> operator>=(vfloat<4> a, vfloat<4> b) { return _mm_cmpge_ps(a.m, b.m); }
RTK_INLINE vbool<4> operator==(vfloat<4> a, vfloat<4> b) { return _mm_cmpeq_ps(a.m, b.m); }
RTK_INLINE vbool<4> operator!=(vfloat<4> a, vfloat<4> b) { return _mm_cmpneq_ps(a.m, b.m); }
RTK_INLINE vfloat<4> select(vbool<4> m, vfloat<4> t, vfloat<4> f) { return _mm_blendv_ps(f.m, t.m, m.m); }
// [ch01-sse4-compare]
RTK_INLINE vbool<4> isnan(vfloat<4> a) { return _mm_cmpunord_ps(a.m, a.m); }

/// cvttps2dq and cvtps2dq return INT_MIN ("integer indefinite") for NaN and out-of-range
/// lanes, which is the portable rule.
RTK_INLINE vint<4> to_int_trunc(vfloat<4> a) { return _mm_cvttps_epi32(a.m); }
RTK_INLINE vint<4> to_int_round(vfloat<4> a) { return _mm_cvtps_epi32(a.m); }
RTK_INLINE vfloat<4> to_float(vint<4> a) { return _mm_cvtepi32_ps(a.m); }

// [ch01-sse4-reduce]
// Lanes (0, 2) and (1, 3) first, then the two partial results: the portable halving order,
// with the lower lane always the first operand.
RTK_INLINE float reduce_add(vfloat<4> a) {
  const __m128 h = _mm_add_ps(a.m, _mm_movehl_ps(a.m, a.m));
  return _mm_cvtss_f32(_mm_add_ss(h, _mm_shuffle_ps(h, h, 1)));
}
RTK_INLINE float reduce_min(vfloat<4> a) {
  const __m128 h = _mm_min_ps(a.m, _mm_movehl_ps(a.m, a.m));
  return _mm_cvtss_f32(_mm_min_ss(h, _mm_shuffle_ps(h, h, 1)));
}
RTK_INLINE float reduce_max(vfloat<4> a) {
  const __m128 h = _mm_max_ps(a.m, _mm_movehl_ps(a.m, a.m));
  return _mm_cvtss_f32(_mm_max_ss(h, _mm_shuffle_ps(h, h, 1)));
}
// [ch01-sse4-reduce]
RTK_INLINE int min_index(vfloat<4> a) {
  const uint32_t m = movemask(a == vfloat<4>(reduce_min(a)));
  return m ? bit_scan_forward(m) : 0;
}

template <int i0, int i1, int i2, int i3>
RTK_INLINE vfloat<4> shuffle(vfloat<4> a) {
  static_assert(0 <= (i0 | i1 | i2 | i3) && (i0 | i1 | i2 | i3) < 4, "shuffle: lanes 0 to 3");
  return _mm_shuffle_ps(a.m, a.m, _MM_SHUFFLE(i3, i2, i1, i0));
}
template <int i>
RTK_INLINE vfloat<4> broadcast_lane(vfloat<4> a) {
  static_assert(0 <= i && i < 4, "broadcast_lane: no such lane");
  return _mm_shuffle_ps(a.m, a.m, _MM_SHUFFLE(i, i, i, i));
}

}  // namespace rtk::RTK_ISA
