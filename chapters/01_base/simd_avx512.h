/// \file
/// The AVX-512 backend: vbool<16> as a mask register (__mmask16), vint<16> and vfloat<16> in
/// one 512-bit register each.
///
/// Every operation of simd_portable.h has an exact-match overload here, with the portable
/// semantics. Only AVX-512F instructions are used for the sixteen-lane types; the variant's
/// other extensions (VL, DQ, BW, CD) serve the four- and eight-lane types of simd_sse4.h and
/// simd_avx2.h, compiled into the same translation unit.
#pragma once

#ifndef RTK_ISA
#error "simd_avx512.h belongs to kernel sources compiled once per ISA (see cmake/rtk_isa.cmake)"
#endif
#if !defined(__AVX512F__)
#error "simd_avx512.h needs AVX-512F (-mavx512f)"
#endif

#include "01_base/simd_avx2.h"

namespace rtk::RTK_ISA {

// [ch01-avx512-vbool]
/// Sixteen lanes of mask in a mask register: bit i is lane i, so movemask is free and
/// from_bits is a move.
template <>
struct vbool<16> {
  static constexpr int size = 16;
  __mmask16 m;

  vbool() = default;
  /// All lanes set to `b`.
  vbool(bool b) : m(b ? 0xFFFF : 0) {}
  /// The lanes whose bit is set in `bits` (bit i is lane i).
  static vbool from_bits(uint32_t bits) { return from_mask(__mmask16(bits)); }
  /// The mask register as it is (compares and blends use it directly).
  static vbool from_mask(__mmask16 k) {
    vbool r;
    r.m = k;
    return r;
  }
  bool operator[](int i) const { return (m >> i) & 1; }
};
// [ch01-avx512-vbool]

RTK_INLINE vbool<16> operator&(vbool<16> a, vbool<16> b) { return vbool<16>::from_mask(_kand_mask16(a.m, b.m)); }
RTK_INLINE vbool<16> operator|(vbool<16> a, vbool<16> b) { return vbool<16>::from_mask(_kor_mask16(a.m, b.m)); }
RTK_INLINE vbool<16> operator^(vbool<16> a, vbool<16> b) { return vbool<16>::from_mask(_kxor_mask16(a.m, b.m)); }
RTK_INLINE vbool<16> operator!(vbool<16> a) { return vbool<16>::from_mask(_knot_mask16(a.m)); }
RTK_INLINE uint32_t movemask(vbool<16> a) { return uint32_t(a.m); }
RTK_INLINE bool any(vbool<16> a) { return a.m != 0; }
RTK_INLINE bool all(vbool<16> a) { return a.m == 0xFFFF; }
RTK_INLINE bool none(vbool<16> a) { return a.m == 0; }

/// Sixteen 32-bit signed integers.
template <>
struct vint<16> {
  static constexpr int size = 16;
  __m512i m;

  vint() = default;
  vint(__m512i x) : m(x) {}
  vint(int32_t s) : m(_mm512_set1_epi32(s)) {}
  static vint load(const int32_t* p) { return _mm512_load_si512(p); }
  static vint loadu(const int32_t* p) { return _mm512_loadu_si512(p); }
  void store(int32_t* p) const { _mm512_store_si512(p, m); }
  void storeu(int32_t* p) const { _mm512_storeu_si512(p, m); }
  /// The lane indices 0, 1, ..., 15.
  static vint iota() { return _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15); }
  int32_t operator[](int i) const {
    alignas(64) int32_t lanes[16];
    store(lanes);
    return lanes[i];
  }
  /// The lower and upper eight lanes (a helper of this backend, not a wrapper operation).
  vint<8> low() const { return _mm512_castsi512_si256(m); }
  vint<8> high() const { return _mm512_extracti64x4_epi64(m, 1); }
};

RTK_INLINE vint<16> operator+(vint<16> a, vint<16> b) { return _mm512_add_epi32(a.m, b.m); }
RTK_INLINE vint<16> operator-(vint<16> a, vint<16> b) { return _mm512_sub_epi32(a.m, b.m); }
RTK_INLINE vint<16> operator*(vint<16> a, vint<16> b) { return _mm512_mullo_epi32(a.m, b.m); }
RTK_INLINE vint<16> operator&(vint<16> a, vint<16> b) { return _mm512_and_si512(a.m, b.m); }
RTK_INLINE vint<16> operator|(vint<16> a, vint<16> b) { return _mm512_or_si512(a.m, b.m); }
RTK_INLINE vint<16> operator^(vint<16> a, vint<16> b) { return _mm512_xor_si512(a.m, b.m); }
RTK_INLINE vint<16> operator<<(vint<16> a, int n) { return _mm512_sll_epi32(a.m, _mm_cvtsi32_si128(n)); }
RTK_INLINE vint<16> operator>>(vint<16> a, int n) { return _mm512_sra_epi32(a.m, _mm_cvtsi32_si128(n)); }
RTK_INLINE vint<16> srl(vint<16> a, int n) { return _mm512_srl_epi32(a.m, _mm_cvtsi32_si128(n)); }
RTK_INLINE vbool<16> operator==(vint<16> a, vint<16> b) { return vbool<16>::from_mask(_mm512_cmpeq_epi32_mask(a.m, b.m)); }
RTK_INLINE vbool<16> operator!=(vint<16> a, vint<16> b) { return vbool<16>::from_mask(_mm512_cmpneq_epi32_mask(a.m, b.m)); }
RTK_INLINE vbool<16> operator<(vint<16> a, vint<16> b) { return vbool<16>::from_mask(_mm512_cmplt_epi32_mask(a.m, b.m)); }
RTK_INLINE vbool<16> operator>(vint<16> a, vint<16> b) { return vbool<16>::from_mask(_mm512_cmpgt_epi32_mask(a.m, b.m)); }
RTK_INLINE vint<16> min(vint<16> a, vint<16> b) { return _mm512_min_epi32(a.m, b.m); }
RTK_INLINE vint<16> max(vint<16> a, vint<16> b) { return _mm512_max_epi32(a.m, b.m); }
RTK_INLINE vint<16> select(vbool<16> m, vint<16> t, vint<16> f) { return _mm512_mask_blend_epi32(m.m, f.m, t.m); }
RTK_INLINE int32_t reduce_add(vint<16> a) { return reduce_add(a.low() + a.high()); }
RTK_INLINE int32_t reduce_min(vint<16> a) { return reduce_min(min(a.low(), a.high())); }
RTK_INLINE int32_t reduce_max(vint<16> a) { return reduce_max(max(a.low(), a.high())); }

/// Sixteen floats.
template <>
struct vfloat<16> {
  static constexpr int size = 16;
  __m512 m;

  vfloat() = default;
  vfloat(__m512 x) : m(x) {}
  /// All lanes set to `s` (a broadcast).
  vfloat(float s) : m(_mm512_set1_ps(s)) {}
  static vfloat load(const float* p) { return _mm512_load_ps(p); }
  static vfloat loadu(const float* p) { return _mm512_loadu_ps(p); }
  void store(float* p) const { _mm512_store_ps(p, m); }
  void storeu(float* p) const { _mm512_storeu_ps(p, m); }
  /// Lane i is base[index[i]] (vgatherdps).
  static vfloat gather(const float* base, vint<16> index) { return _mm512_i32gather_ps(index.m, base, 4); }
  float operator[](int i) const {
    alignas(64) float lanes[16];
    store(lanes);
    return lanes[i];
  }
  /// The lower and upper eight lanes (a helper of this backend, not a wrapper operation).
  vfloat<8> low() const { return _mm512_castps512_ps256(m); }
  vfloat<8> high() const { return _mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(m), 1)); }
};

// No portable loop can be instantiated for these types (they have no member `v`).
static_assert(!portable_lanes<vfloat<16>> && !portable_lanes<vint<16>> && !portable_lanes<vbool<16>>);

RTK_INLINE vfloat<16> operator+(vfloat<16> a, vfloat<16> b) { return _mm512_add_ps(a.m, b.m); }
RTK_INLINE vfloat<16> operator-(vfloat<16> a, vfloat<16> b) { return _mm512_sub_ps(a.m, b.m); }
RTK_INLINE vfloat<16> operator*(vfloat<16> a, vfloat<16> b) { return _mm512_mul_ps(a.m, b.m); }
RTK_INLINE vfloat<16> operator/(vfloat<16> a, vfloat<16> b) { return _mm512_div_ps(a.m, b.m); }
RTK_INLINE vfloat<16>& operator+=(vfloat<16>& a, vfloat<16> b) { return a = a + b; }
RTK_INLINE vfloat<16>& operator-=(vfloat<16>& a, vfloat<16> b) { return a = a - b; }
RTK_INLINE vfloat<16>& operator*=(vfloat<16>& a, vfloat<16> b) { return a = a * b; }
RTK_INLINE vfloat<16>& operator/=(vfloat<16>& a, vfloat<16> b) { return a = a / b; }

// Bit operations on floats go through the integer domain: the float forms need AVX-512DQ.
RTK_INLINE vint<16> as_int(vfloat<16> a) { return _mm512_castps_si512(a.m); }
RTK_INLINE vfloat<16> as_float(vint<16> a) { return _mm512_castsi512_ps(a.m); }
RTK_INLINE vfloat<16> operator-(vfloat<16> a) { return as_float(as_int(a) ^ vint<16>(int32_t(0x80000000u))); }

/// vminps and vmaxps: the second operand wins unless the first is strictly smaller (larger).
RTK_INLINE vfloat<16> min(vfloat<16> a, vfloat<16> b) { return _mm512_min_ps(a.m, b.m); }
RTK_INLINE vfloat<16> max(vfloat<16> a, vfloat<16> b) { return _mm512_max_ps(a.m, b.m); }

RTK_INLINE vfloat<16> fmadd(vfloat<16> a, vfloat<16> b, vfloat<16> c) { return _mm512_fmadd_ps(a.m, b.m, c.m); }
RTK_INLINE vfloat<16> fmsub(vfloat<16> a, vfloat<16> b, vfloat<16> c) { return _mm512_fmsub_ps(a.m, b.m, c.m); }
RTK_INLINE vfloat<16> fnmadd(vfloat<16> a, vfloat<16> b, vfloat<16> c) { return _mm512_fnmadd_ps(a.m, b.m, c.m); }
RTK_INLINE vfloat<16> fnmsub(vfloat<16> a, vfloat<16> b, vfloat<16> c) { return _mm512_fnmsub_ps(a.m, b.m, c.m); }

RTK_INLINE vfloat<16> sqrt(vfloat<16> a) { return _mm512_sqrt_ps(a.m); }
// vrndscaleps with scale 0 rounds to an integer in the given direction.
RTK_INLINE vfloat<16> floor(vfloat<16> a) { return _mm512_roundscale_ps(a.m, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC); }
RTK_INLINE vfloat<16> ceil(vfloat<16> a) { return _mm512_roundscale_ps(a.m, _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC); }

/// vrcp14ps: relative error below 2^-14, denormal inputs read as they are (see the portable
/// rcp_fast for the domain every backend shares).
RTK_INLINE vfloat<16> rcp_fast(vfloat<16> a) { return _mm512_rcp14_ps(a.m); }
/// The estimate plus one Newton-Raphson step, keeping the estimate where the step makes NaN.
RTK_INLINE vfloat<16> rcp(vfloat<16> a) {
  const vfloat<16> x = rcp_fast(a);
  const vfloat<16> refined = fmadd(x, fnmadd(a, x, vfloat<16>(1.0f)), x);
  return _mm512_mask_blend_ps(_mm512_cmp_ps_mask(refined.m, refined.m, _CMP_UNORD_Q), refined.m, x.m);
}

RTK_INLINE vfloat<16> abs(vfloat<16> a) { return as_float(as_int(a) & vint<16>(0x7FFFFFFF)); }
RTK_INLINE vfloat<16> signmask(vfloat<16> a) { return as_float(as_int(a) & vint<16>(int32_t(0x80000000u))); }
RTK_INLINE vfloat<16> xorsign(vfloat<16> a, vfloat<16> b) { return as_float(as_int(a) ^ as_int(signmask(b))); }
RTK_INLINE vfloat<16> copysign(vfloat<16> a, vfloat<16> b) { return as_float(as_int(abs(a)) | as_int(signmask(b))); }
/// The sign bits: a lane is negative as an integer exactly when its sign bit is set.
RTK_INLINE uint32_t sign_bits(vfloat<16> a) { return _mm512_cmplt_epi32_mask(as_int(a).m, _mm512_setzero_si512()); }

// [ch01-avx512-compare]
// Compares write a mask register; ordered predicates (_OQ) except `!=` (_UQ).
RTK_INLINE vbool<16> operator<(vfloat<16> a, vfloat<16> b) { return vbool<16>::from_mask(_mm512_cmp_ps_mask(a.m, b.m, _CMP_LT_OQ)); }
RTK_INLINE vbool<16> operator<=(vfloat<16> a, vfloat<16> b) { return vbool<16>::from_mask(_mm512_cmp_ps_mask(a.m, b.m, _CMP_LE_OQ)); }
RTK_INLINE vbool<16> operator>(vfloat<16> a, vfloat<16> b) { return vbool<16>::from_mask(_mm512_cmp_ps_mask(a.m, b.m, _CMP_GT_OQ)); }
RTK_INLINE vbool<16> operator>=(vfloat<16> a, vfloat<16> b) { return vbool<16>::from_mask(_mm512_cmp_ps_mask(a.m, b.m, _CMP_GE_OQ)); }
RTK_INLINE vbool<16> operator==(vfloat<16> a, vfloat<16> b) { return vbool<16>::from_mask(_mm512_cmp_ps_mask(a.m, b.m, _CMP_EQ_OQ)); }
RTK_INLINE vbool<16> operator!=(vfloat<16> a, vfloat<16> b) { return vbool<16>::from_mask(_mm512_cmp_ps_mask(a.m, b.m, _CMP_NEQ_UQ)); }
RTK_INLINE vfloat<16> select(vbool<16> m, vfloat<16> t, vfloat<16> f) { return _mm512_mask_blend_ps(m.m, f.m, t.m); }
// [ch01-avx512-compare]
RTK_INLINE vbool<16> isnan(vfloat<16> a) { return vbool<16>::from_mask(_mm512_cmp_ps_mask(a.m, a.m, _CMP_UNORD_Q)); }

/// NaN and out-of-range lanes give INT_MIN, as in the portable rule.
RTK_INLINE vint<16> to_int_trunc(vfloat<16> a) { return _mm512_cvttps_epi32(a.m); }
RTK_INLINE vint<16> to_int_round(vfloat<16> a) { return _mm512_cvtps_epi32(a.m); }
RTK_INLINE vfloat<16> to_float(vint<16> a) { return _mm512_cvtepi32_ps(a.m); }

// Lane i meets lane i + 8 first (the lower half is the first operand), then the eight-lane order.
RTK_INLINE float reduce_add(vfloat<16> a) { return reduce_add(a.low() + a.high()); }
RTK_INLINE float reduce_min(vfloat<16> a) { return reduce_min(min(a.low(), a.high())); }
RTK_INLINE float reduce_max(vfloat<16> a) { return reduce_max(max(a.low(), a.high())); }
RTK_INLINE int min_index(vfloat<16> a) {
  const uint32_t m = movemask(a == vfloat<16>(reduce_min(a)));
  return m ? bit_scan_forward(m) : 0;
}

/// vpermilps: the same four-lane shuffle in each 128-bit quarter.
template <int i0, int i1, int i2, int i3>
RTK_INLINE vfloat<16> shuffle(vfloat<16> a) {
  static_assert(0 <= (i0 | i1 | i2 | i3) && (i0 | i1 | i2 | i3) < 4, "shuffle: lanes 0 to 3");
  return _mm512_permute_ps(a.m, _MM_SHUFFLE(i3, i2, i1, i0));
}
/// vpermps with a constant index: any lane, across the whole register.
template <int i>
RTK_INLINE vfloat<16> broadcast_lane(vfloat<16> a) {
  static_assert(0 <= i && i < 16, "broadcast_lane: no such lane");
  return _mm512_permutexvar_ps(_mm512_set1_epi32(i), a.m);
}

}  // namespace rtk::RTK_ISA
