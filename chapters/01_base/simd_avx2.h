/// \file
/// The AVX2 backend: vbool<8>, vint<8> and vfloat<8>, one 256-bit register each.
///
/// Every operation of simd_portable.h has an exact-match overload here, with the portable
/// semantics. AVX2 machines have FMA, so the fmadd family rounds once, as the portable backend
/// does. The AVX-512 variant uses this header for its eight-lane vectors (with rcp14ps).
#pragma once

#ifndef RTK_ISA
#error "simd_avx2.h belongs to kernel sources compiled once per ISA (see cmake/rtk_isa.cmake)"
#endif
#if !defined(__AVX2__) || !defined(__FMA__)
#error "simd_avx2.h needs AVX2 and FMA (-mavx2 -mfma)"
#endif

#include "01_base/simd_sse4.h"

namespace rtk::RTK_ISA {

/// Eight lanes of mask, all ones or all zeros each.
template <>
struct vbool<8> {
  static constexpr int size = 8;
  __m256 m;

  vbool() = default;
  vbool(__m256 mask) : m(mask) {}
  /// All lanes set to `b`.
  vbool(bool b) : m(_mm256_castsi256_ps(_mm256_set1_epi32(b ? -1 : 0))) {}
  /// The lanes whose bit is set in `bits` (bit i is lane i).
  static vbool from_bits(uint32_t bits) {
    const __m256i lane_bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    const __m256i masked = _mm256_and_si256(_mm256_set1_epi32(int32_t(bits)), lane_bit);
    return _mm256_castsi256_ps(_mm256_cmpeq_epi32(masked, lane_bit));
  }
  bool operator[](int i) const { return (_mm256_movemask_ps(m) >> i) & 1; }
};

RTK_INLINE vbool<8> operator&(vbool<8> a, vbool<8> b) { return _mm256_and_ps(a.m, b.m); }
RTK_INLINE vbool<8> operator|(vbool<8> a, vbool<8> b) { return _mm256_or_ps(a.m, b.m); }
RTK_INLINE vbool<8> operator^(vbool<8> a, vbool<8> b) { return _mm256_xor_ps(a.m, b.m); }
RTK_INLINE vbool<8> operator!(vbool<8> a) { return _mm256_xor_ps(a.m, vbool<8>(true).m); }
RTK_INLINE uint32_t movemask(vbool<8> a) { return uint32_t(_mm256_movemask_ps(a.m)); }
RTK_INLINE bool any(vbool<8> a) { return movemask(a) != 0; }
RTK_INLINE bool all(vbool<8> a) { return movemask(a) == 0xFF; }
RTK_INLINE bool none(vbool<8> a) { return movemask(a) == 0; }

/// Eight 32-bit signed integers.
template <>
struct vint<8> {
  static constexpr int size = 8;
  __m256i m;

  vint() = default;
  vint(__m256i x) : m(x) {}
  vint(int32_t s) : m(_mm256_set1_epi32(s)) {}
  static vint load(const int32_t* p) { return _mm256_load_si256(reinterpret_cast<const __m256i*>(p)); }
  static vint loadu(const int32_t* p) { return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)); }
  void store(int32_t* p) const { _mm256_store_si256(reinterpret_cast<__m256i*>(p), m); }
  void storeu(int32_t* p) const { _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), m); }
  /// The lane indices 0, 1, ..., 7.
  static vint iota() { return _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7); }
  int32_t operator[](int i) const {
    alignas(32) int32_t lanes[8];
    store(lanes);
    return lanes[i];
  }
  /// The lower and upper four lanes (a helper of this backend, not a wrapper operation).
  vint<4> low() const { return _mm256_castsi256_si128(m); }
  vint<4> high() const { return _mm256_extracti128_si256(m, 1); }
};

RTK_INLINE vint<8> operator+(vint<8> a, vint<8> b) { return _mm256_add_epi32(a.m, b.m); }
RTK_INLINE vint<8> operator-(vint<8> a, vint<8> b) { return _mm256_sub_epi32(a.m, b.m); }
RTK_INLINE vint<8> operator*(vint<8> a, vint<8> b) { return _mm256_mullo_epi32(a.m, b.m); }
RTK_INLINE vint<8> operator&(vint<8> a, vint<8> b) { return _mm256_and_si256(a.m, b.m); }
RTK_INLINE vint<8> operator|(vint<8> a, vint<8> b) { return _mm256_or_si256(a.m, b.m); }
RTK_INLINE vint<8> operator^(vint<8> a, vint<8> b) { return _mm256_xor_si256(a.m, b.m); }
RTK_INLINE vint<8> operator<<(vint<8> a, int n) { return _mm256_sll_epi32(a.m, _mm_cvtsi32_si128(n)); }
RTK_INLINE vint<8> operator>>(vint<8> a, int n) { return _mm256_sra_epi32(a.m, _mm_cvtsi32_si128(n)); }
RTK_INLINE vint<8> srl(vint<8> a, int n) { return _mm256_srl_epi32(a.m, _mm_cvtsi32_si128(n)); }
RTK_INLINE vbool<8> operator==(vint<8> a, vint<8> b) { return _mm256_castsi256_ps(_mm256_cmpeq_epi32(a.m, b.m)); }
RTK_INLINE vbool<8> operator!=(vint<8> a, vint<8> b) { return !(a == b); }
RTK_INLINE vbool<8> operator<(vint<8> a, vint<8> b) { return _mm256_castsi256_ps(_mm256_cmpgt_epi32(b.m, a.m)); }
RTK_INLINE vbool<8> operator>(vint<8> a, vint<8> b) { return _mm256_castsi256_ps(_mm256_cmpgt_epi32(a.m, b.m)); }
RTK_INLINE vint<8> min(vint<8> a, vint<8> b) { return _mm256_min_epi32(a.m, b.m); }
RTK_INLINE vint<8> max(vint<8> a, vint<8> b) { return _mm256_max_epi32(a.m, b.m); }
RTK_INLINE vint<8> select(vbool<8> m, vint<8> t, vint<8> f) {
  return _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(f.m), _mm256_castsi256_ps(t.m), m.m));
}
RTK_INLINE int32_t reduce_add(vint<8> a) { return reduce_add(a.low() + a.high()); }
RTK_INLINE int32_t reduce_min(vint<8> a) { return reduce_min(min(a.low(), a.high())); }
RTK_INLINE int32_t reduce_max(vint<8> a) { return reduce_max(max(a.low(), a.high())); }

/// Eight floats.
template <>
struct vfloat<8> {
  static constexpr int size = 8;
  __m256 m;

  vfloat() = default;
  vfloat(__m256 x) : m(x) {}
  /// All lanes set to `s` (a broadcast).
  vfloat(float s) : m(_mm256_set1_ps(s)) {}
  static vfloat load(const float* p) { return _mm256_load_ps(p); }
  static vfloat loadu(const float* p) { return _mm256_loadu_ps(p); }
  void store(float* p) const { _mm256_store_ps(p, m); }
  void storeu(float* p) const { _mm256_storeu_ps(p, m); }
  /// Lane i is base[index[i]] (vgatherdps).
  static vfloat gather(const float* base, vint<8> index) { return _mm256_i32gather_ps(base, index.m, 4); }
  float operator[](int i) const {
    alignas(32) float lanes[8];
    store(lanes);
    return lanes[i];
  }
  /// Lanes 0-3 from `low`, 4-7 from `high`, and back (helpers of this backend, not wrapper
  /// operations).
  vfloat(vfloat<4> low, vfloat<4> high) : m(_mm256_set_m128(high.m, low.m)) {}
  vfloat<4> low() const { return _mm256_castps256_ps128(m); }
  vfloat<4> high() const { return _mm256_extractf128_ps(m, 1); }
};

// No portable loop can be instantiated for these types (they have no member `v`).
static_assert(!portable_lanes<vfloat<8>> && !portable_lanes<vint<8>> && !portable_lanes<vbool<8>>);

RTK_INLINE vfloat<8> operator+(vfloat<8> a, vfloat<8> b) { return _mm256_add_ps(a.m, b.m); }
RTK_INLINE vfloat<8> operator-(vfloat<8> a, vfloat<8> b) { return _mm256_sub_ps(a.m, b.m); }
RTK_INLINE vfloat<8> operator*(vfloat<8> a, vfloat<8> b) { return _mm256_mul_ps(a.m, b.m); }
RTK_INLINE vfloat<8> operator/(vfloat<8> a, vfloat<8> b) { return _mm256_div_ps(a.m, b.m); }
RTK_INLINE vfloat<8>& operator+=(vfloat<8>& a, vfloat<8> b) { return a = a + b; }
RTK_INLINE vfloat<8>& operator-=(vfloat<8>& a, vfloat<8> b) { return a = a - b; }
RTK_INLINE vfloat<8>& operator*=(vfloat<8>& a, vfloat<8> b) { return a = a * b; }
RTK_INLINE vfloat<8>& operator/=(vfloat<8>& a, vfloat<8> b) { return a = a / b; }
RTK_INLINE vfloat<8> operator-(vfloat<8> a) { return _mm256_xor_ps(a.m, _mm256_set1_ps(-0.0f)); }

/// vminps and vmaxps: the second operand wins unless the first is strictly smaller (larger).
RTK_INLINE vfloat<8> min(vfloat<8> a, vfloat<8> b) { return _mm256_min_ps(a.m, b.m); }
RTK_INLINE vfloat<8> max(vfloat<8> a, vfloat<8> b) { return _mm256_max_ps(a.m, b.m); }

RTK_INLINE vfloat<8> fmadd(vfloat<8> a, vfloat<8> b, vfloat<8> c) { return _mm256_fmadd_ps(a.m, b.m, c.m); }
RTK_INLINE vfloat<8> fmsub(vfloat<8> a, vfloat<8> b, vfloat<8> c) { return _mm256_fmsub_ps(a.m, b.m, c.m); }
RTK_INLINE vfloat<8> fnmadd(vfloat<8> a, vfloat<8> b, vfloat<8> c) { return _mm256_fnmadd_ps(a.m, b.m, c.m); }
RTK_INLINE vfloat<8> fnmsub(vfloat<8> a, vfloat<8> b, vfloat<8> c) { return _mm256_fnmsub_ps(a.m, b.m, c.m); }

RTK_INLINE vfloat<8> sqrt(vfloat<8> a) { return _mm256_sqrt_ps(a.m); }
RTK_INLINE vfloat<8> floor(vfloat<8> a) { return _mm256_round_ps(a.m, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC); }
RTK_INLINE vfloat<8> ceil(vfloat<8> a) { return _mm256_round_ps(a.m, _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC); }

/// The hardware estimate of 1/a (see the portable rcp_fast for its domain).
RTK_INLINE vfloat<8> rcp_fast(vfloat<8> a) {
#if defined(__AVX512VL__)
  return _mm256_rcp14_ps(a.m);
#else
  return _mm256_rcp_ps(a.m);
#endif
}
/// The estimate plus one Newton-Raphson step, keeping the estimate where the step makes NaN.
RTK_INLINE vfloat<8> rcp(vfloat<8> a) {
  const vfloat<8> x = rcp_fast(a);
  const vfloat<8> refined = fmadd(x, fnmadd(a, x, vfloat<8>(1.0f)), x);
  return _mm256_blendv_ps(refined.m, x.m, _mm256_cmp_ps(refined.m, refined.m, _CMP_UNORD_Q));
}

RTK_INLINE vint<8> as_int(vfloat<8> a) { return _mm256_castps_si256(a.m); }
RTK_INLINE vfloat<8> as_float(vint<8> a) { return _mm256_castsi256_ps(a.m); }
RTK_INLINE vfloat<8> abs(vfloat<8> a) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.m); }
RTK_INLINE vfloat<8> signmask(vfloat<8> a) { return _mm256_and_ps(_mm256_set1_ps(-0.0f), a.m); }
RTK_INLINE vfloat<8> xorsign(vfloat<8> a, vfloat<8> b) { return _mm256_xor_ps(a.m, signmask(b).m); }
RTK_INLINE vfloat<8> copysign(vfloat<8> a, vfloat<8> b) { return _mm256_or_ps(abs(a).m, signmask(b).m); }
RTK_INLINE uint32_t sign_bits(vfloat<8> a) { return uint32_t(_mm256_movemask_ps(a.m)); }

// Ordered predicates (_OQ), false with a NaN; `!=` is unordered (_UQ), true with a NaN.
RTK_INLINE vbool<8> operator<(vfloat<8> a, vfloat<8> b) { return _mm256_cmp_ps(a.m, b.m, _CMP_LT_OQ); }
RTK_INLINE vbool<8> operator<=(vfloat<8> a, vfloat<8> b) { return _mm256_cmp_ps(a.m, b.m, _CMP_LE_OQ); }
RTK_INLINE vbool<8> operator>(vfloat<8> a, vfloat<8> b) { return _mm256_cmp_ps(a.m, b.m, _CMP_GT_OQ); }
RTK_INLINE vbool<8> operator>=(vfloat<8> a, vfloat<8> b) { return _mm256_cmp_ps(a.m, b.m, _CMP_GE_OQ); }
RTK_INLINE vbool<8> operator==(vfloat<8> a, vfloat<8> b) { return _mm256_cmp_ps(a.m, b.m, _CMP_EQ_OQ); }
RTK_INLINE vbool<8> operator!=(vfloat<8> a, vfloat<8> b) { return _mm256_cmp_ps(a.m, b.m, _CMP_NEQ_UQ); }
RTK_INLINE vfloat<8> select(vbool<8> m, vfloat<8> t, vfloat<8> f) { return _mm256_blendv_ps(f.m, t.m, m.m); }
RTK_INLINE vbool<8> isnan(vfloat<8> a) { return _mm256_cmp_ps(a.m, a.m, _CMP_UNORD_Q); }

/// NaN and out-of-range lanes give INT_MIN, as in the portable rule.
RTK_INLINE vint<8> to_int_trunc(vfloat<8> a) { return _mm256_cvttps_epi32(a.m); }
RTK_INLINE vint<8> to_int_round(vfloat<8> a) { return _mm256_cvtps_epi32(a.m); }
RTK_INLINE vfloat<8> to_float(vint<8> a) { return _mm256_cvtepi32_ps(a.m); }

// Lane i meets lane i + 4 first (the lower half is the first operand), then the four-lane order.
RTK_INLINE float reduce_add(vfloat<8> a) { return reduce_add(a.low() + a.high()); }
RTK_INLINE float reduce_min(vfloat<8> a) { return reduce_min(min(a.low(), a.high())); }
RTK_INLINE float reduce_max(vfloat<8> a) { return reduce_max(max(a.low(), a.high())); }
RTK_INLINE int min_index(vfloat<8> a) {
  const uint32_t m = movemask(a == vfloat<8>(reduce_min(a)));
  return m ? bit_scan_forward(m) : 0;
}

/// vpermilps: the same four-lane shuffle in each 128-bit half.
template <int i0, int i1, int i2, int i3>
RTK_INLINE vfloat<8> shuffle(vfloat<8> a) {
  static_assert(0 <= (i0 | i1 | i2 | i3) && (i0 | i1 | i2 | i3) < 4, "shuffle: lanes 0 to 3");
  return _mm256_permute_ps(a.m, _MM_SHUFFLE(i3, i2, i1, i0));
}
/// vpermps with a constant index: any lane, across the halves.
template <int i>
RTK_INLINE vfloat<8> broadcast_lane(vfloat<8> a) {
  static_assert(0 <= i && i < 8, "broadcast_lane: no such lane");
  return _mm256_permutevar8x32_ps(a.m, _mm256_set1_epi32(i));
}

}  // namespace rtk::RTK_ISA
