/// \file
/// The portable SIMD backend: vbool<N>, vint<N> and vfloat<N> as plain arrays, for any N.
///
/// This file is the specification of every SIMD backend. Where IEEE arithmetic leaves a choice,
/// the portable backend copies what SSE does, so that the intrinsic backends can be compared
/// with it bit for bit:
/// - min(a, b) is `a < b ? a : b` and max(a, b) is `a > b ? a : b`: with a NaN, or with -0 and
///   +0, the second argument is returned;
/// - comparisons are ordered (false with a NaN), except `!=`, which is true with a NaN;
/// - float to int conversion of NaN or of a value out of range gives INT_MIN (0x80000000);
/// - horizontal reductions combine lane i with lane i + N/2, then halve again, so their
///   rounding and NaN behaviour is that of the shuffle-and-add code the ISAs use;
/// - fmadd(a, b, c) is a * b + c rounded once where the ISA has FMA, and twice where it has not:
///   the one operation whose result the variants may legitimately disagree on (by one rounding
///   of the product), together with the reciprocal approximations rcp_fast and rcp;
/// - a NaN that arithmetic produces is some NaN: x86 passes on the first operand's payload, and
///   the compiler may swap the operands of + and *, so payloads are not part of the contract.
///   Operations that only move bits (loads, select, min, max, shuffles, sign operations) keep
///   every bit, NaN payloads included.
///
/// The intrinsic backends specialise vbool, vint and vfloat for their widths and name the
/// register `m`, never `v`: a portable loop instantiated for a native width therefore fails to
/// compile instead of running silently lane by lane.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "01_base/platform.h"

namespace rtk::RTK_ISA {

template <int N> struct vbool;
template <int N> struct vint;
template <int N> struct vfloat;

/// Whether a wrapper type keeps its lanes in the portable array `v` (the intrinsic backends
/// assert that theirs do not, so no portable loop can run on a native width).
template <class T>
concept portable_lanes = requires(T x) { x.v; };

// [ch01-portable-vbool]
/// A mask of N lanes, the result of comparing vectors.
template <int N>
struct vbool {
  static constexpr int size = N;
  bool v[N];

  vbool() = default;
  /// All lanes set to `b`.
  vbool(bool b) { for (int i = 0; i < N; ++i) v[i] = b; }
  /// The lanes whose bit is set in `bits` (bit i is lane i).
  static vbool from_bits(uint32_t bits) { vbool r; for (int i = 0; i < N; ++i) r.v[i] = (bits >> i) & 1; return r; }
  bool operator[](int i) const { return v[i]; }
};
// [ch01-portable-vbool]

template <int N> vbool<N> operator&(vbool<N> a, vbool<N> b) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] && b.v[i]; return r; }
template <int N> vbool<N> operator|(vbool<N> a, vbool<N> b) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] || b.v[i]; return r; }
template <int N> vbool<N> operator^(vbool<N> a, vbool<N> b) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] != b.v[i]; return r; }
template <int N> vbool<N> operator!(vbool<N> a) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = !a.v[i]; return r; }
/// Lane i of the mask becomes bit i of the result.
template <int N> uint32_t movemask(vbool<N> a) { uint32_t m = 0; for (int i = 0; i < N; ++i) m |= uint32_t(a.v[i]) << i; return m; }
template <int N> bool any(vbool<N> a) { return movemask(a) != 0; }
template <int N> bool all(vbool<N> a) { return movemask(a) == (N == 32 ? ~0u : (1u << N) - 1); }
template <int N> bool none(vbool<N> a) { return movemask(a) == 0; }

/// N 32-bit signed integers.
template <int N>
struct vint {
  static constexpr int size = N;
  int32_t v[N];

  vint() = default;
  vint(int32_t s) { for (int i = 0; i < N; ++i) v[i] = s; }
  static vint load(const int32_t* p) { vint r; std::memcpy(r.v, p, sizeof r.v); return r; }
  static vint loadu(const int32_t* p) { return load(p); }
  void store(int32_t* p) const { std::memcpy(p, v, sizeof v); }
  void storeu(int32_t* p) const { store(p); }
  /// The lane indices 0, 1, ..., N-1.
  static vint iota() { vint r; for (int i = 0; i < N; ++i) r.v[i] = i; return r; }
  int32_t operator[](int i) const { return v[i]; }
};

// Integer arithmetic wraps around (two's complement), as the SIMD instructions do.
#define RTK_VINT_BINARY(op)                                                                     \
  template <int N> vint<N> operator op(vint<N> a, vint<N> b) {                                 \
    vint<N> r;                                                                                 \
    for (int i = 0; i < N; ++i) r.v[i] = int32_t(uint32_t(a.v[i]) op uint32_t(b.v[i]));        \
    return r;                                                                                  \
  }
RTK_VINT_BINARY(+)
RTK_VINT_BINARY(-)
RTK_VINT_BINARY(*)
RTK_VINT_BINARY(&)
RTK_VINT_BINARY(|)
RTK_VINT_BINARY(^)
#undef RTK_VINT_BINARY
/// Shifts by the same count n in every lane, 0 <= n < 32: left, arithmetic right, logical right.
template <int N> vint<N> operator<<(vint<N> a, int n) { vint<N> r; for (int i = 0; i < N; ++i) r.v[i] = int32_t(uint32_t(a.v[i]) << n); return r; }
template <int N> vint<N> operator>>(vint<N> a, int n) { vint<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] >> n; return r; }
template <int N> vint<N> srl(vint<N> a, int n) { vint<N> r; for (int i = 0; i < N; ++i) r.v[i] = int32_t(uint32_t(a.v[i]) >> n); return r; }
template <int N> vbool<N> operator==(vint<N> a, vint<N> b) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] == b.v[i]; return r; }
template <int N> vbool<N> operator!=(vint<N> a, vint<N> b) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] != b.v[i]; return r; }
template <int N> vbool<N> operator<(vint<N> a, vint<N> b) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] < b.v[i]; return r; }
template <int N> vbool<N> operator>(vint<N> a, vint<N> b) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] > b.v[i]; return r; }
template <int N> vint<N> min(vint<N> a, vint<N> b) { vint<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] < b.v[i] ? a.v[i] : b.v[i]; return r; }
template <int N> vint<N> max(vint<N> a, vint<N> b) { vint<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] > b.v[i] ? a.v[i] : b.v[i]; return r; }
template <int N> vint<N> select(vbool<N> m, vint<N> t, vint<N> f) { vint<N> r; for (int i = 0; i < N; ++i) r.v[i] = m.v[i] ? t.v[i] : f.v[i]; return r; }
template <int N> int32_t reduce_add(vint<N> a) { uint32_t s = 0; for (int i = 0; i < N; ++i) s += uint32_t(a.v[i]); return int32_t(s); }
template <int N> int32_t reduce_min(vint<N> a) { int32_t m = a.v[0]; for (int i = 1; i < N; ++i) m = a.v[i] < m ? a.v[i] : m; return m; }
template <int N> int32_t reduce_max(vint<N> a) { int32_t m = a.v[0]; for (int i = 1; i < N; ++i) m = a.v[i] > m ? a.v[i] : m; return m; }

// [ch01-portable-vfloat]
/// N floats. Loads and stores come in aligned (`load`, `store`: the address is a multiple of
/// 4 * N bytes, up to 64) and unaligned (`loadu`, `storeu`) forms.
template <int N>
struct vfloat {
  static constexpr int size = N;
  float v[N];

  vfloat() = default;
  /// All lanes set to `s` (a broadcast).
  vfloat(float s) { for (int i = 0; i < N; ++i) v[i] = s; }
  static vfloat load(const float* p) { vfloat r; std::memcpy(r.v, p, sizeof r.v); return r; }
  static vfloat loadu(const float* p) { return load(p); }
  void store(float* p) const { std::memcpy(p, v, sizeof v); }
  void storeu(float* p) const { store(p); }
  /// Lane i is base[index[i]].
  static vfloat gather(const float* base, vint<N> index) { vfloat r; for (int i = 0; i < N; ++i) r.v[i] = base[index.v[i]]; return r; }
  float operator[](int i) const { return v[i]; }
};
// [ch01-portable-vfloat]

#define RTK_VFLOAT_BINARY(op)                                                                   \
  template <int N> vfloat<N> operator op(vfloat<N> a, vfloat<N> b) {                           \
    vfloat<N> r;                                                                               \
    for (int i = 0; i < N; ++i) r.v[i] = a.v[i] op b.v[i];                                     \
    return r;                                                                                  \
  }                                                                                            \
  template <int N> vfloat<N>& operator op##=(vfloat<N>& a, vfloat<N> b) { return a = a op b; }
RTK_VFLOAT_BINARY(+)
RTK_VFLOAT_BINARY(-)
RTK_VFLOAT_BINARY(*)
RTK_VFLOAT_BINARY(/)
#undef RTK_VFLOAT_BINARY
template <int N> vfloat<N> operator-(vfloat<N> a) { vfloat<N> r; for (int i = 0; i < N; ++i) r.v[i] = -a.v[i]; return r; }

// [ch01-portable-minmax]
/// The SSE rule: the second argument wins unless the first is strictly smaller (larger).
template <int N> vfloat<N> min(vfloat<N> a, vfloat<N> b) { vfloat<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] < b.v[i] ? a.v[i] : b.v[i]; return r; }
template <int N> vfloat<N> max(vfloat<N> a, vfloat<N> b) { vfloat<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] > b.v[i] ? a.v[i] : b.v[i]; return r; }
// [ch01-portable-minmax]

/// a * b + c, a * b - c, -(a * b) + c, -(a * b) - c. The portable backend rounds once, like FMA
/// hardware; SSE4 has no FMA and rounds twice.
template <int N> vfloat<N> fmadd(vfloat<N> a, vfloat<N> b, vfloat<N> c) { vfloat<N> r; for (int i = 0; i < N; ++i) r.v[i] = std::fma(a.v[i], b.v[i], c.v[i]); return r; }
template <int N> vfloat<N> fmsub(vfloat<N> a, vfloat<N> b, vfloat<N> c) { vfloat<N> r; for (int i = 0; i < N; ++i) r.v[i] = std::fma(a.v[i], b.v[i], -c.v[i]); return r; }
template <int N> vfloat<N> fnmadd(vfloat<N> a, vfloat<N> b, vfloat<N> c) { vfloat<N> r; for (int i = 0; i < N; ++i) r.v[i] = std::fma(-a.v[i], b.v[i], c.v[i]); return r; }
template <int N> vfloat<N> fnmsub(vfloat<N> a, vfloat<N> b, vfloat<N> c) { vfloat<N> r; for (int i = 0; i < N; ++i) r.v[i] = std::fma(-a.v[i], b.v[i], -c.v[i]); return r; }

template <int N> vfloat<N> sqrt(vfloat<N> a) { vfloat<N> r; for (int i = 0; i < N; ++i) r.v[i] = std::sqrt(a.v[i]); return r; }
template <int N> vfloat<N> floor(vfloat<N> a) { vfloat<N> r; for (int i = 0; i < N; ++i) r.v[i] = std::floor(a.v[i]); return r; }
template <int N> vfloat<N> ceil(vfloat<N> a) { vfloat<N> r; for (int i = 0; i < N; ++i) r.v[i] = std::ceil(a.v[i]); return r; }
// [ch01-portable-rcp]
/// An approximation of 1/a (rcpps; rcp14ps where AVX-512 is allowed; the portable backend returns
/// 1/a exactly). Its domain is 2^-126 <= |a| < 2^125, a normal number whose reciprocal is normal:
/// there the relative error is below 1.5 * 2^-12. Every backend returns +-inf for +-0, +-0 for
/// +-inf and NaN for NaN. Outside the domain only the sign is promised: rcpps reads a denormal a
/// as zero (giving inf) and flushes a tiny reciprocal to zero, where the others do not.
template <int N> vfloat<N> rcp_fast(vfloat<N> a) { vfloat<N> r; for (int i = 0; i < N; ++i) r.v[i] = 1.0f / a.v[i]; return r; }
/// 1/a to within 2^-21 relative error on rcp_fast's domain, with the same special values: the
/// estimate x refined by one Newton-Raphson step, x + x (1 - a x). That step turns 0 * inf into
/// NaN for a = +-0 and a = +-inf, so the backends keep the estimate wherever the step gives NaN.
template <int N> vfloat<N> rcp(vfloat<N> a) { return rcp_fast(a); }
// [ch01-portable-rcp]

// Sign-bit operations work on the bits, so they treat -0, NaN and infinities alike.
template <int N> vint<N> as_int(vfloat<N> a) { vint<N> r; std::memcpy(r.v, a.v, sizeof r.v); return r; }
template <int N> vfloat<N> as_float(vint<N> a) { vfloat<N> r; std::memcpy(r.v, a.v, sizeof r.v); return r; }
/// |a|: the sign bit cleared.
template <int N> vfloat<N> abs(vfloat<N> a) { return as_float(as_int(a) & vint<N>(0x7FFFFFFF)); }
/// a with only its sign bit kept (-0 or +0).
template <int N> vfloat<N> signmask(vfloat<N> a) { return as_float(as_int(a) & vint<N>(int32_t(0x80000000u))); }
/// a with its sign flipped where b's sign bit is set.
template <int N> vfloat<N> xorsign(vfloat<N> a, vfloat<N> b) { return as_float(as_int(a) ^ (as_int(b) & vint<N>(int32_t(0x80000000u)))); }
/// |a| with the sign of b.
template <int N> vfloat<N> copysign(vfloat<N> a, vfloat<N> b) { return as_float((as_int(a) & vint<N>(0x7FFFFFFF)) | (as_int(b) & vint<N>(int32_t(0x80000000u)))); }
/// The sign bits as a bit mask (movmskps).
template <int N> uint32_t sign_bits(vfloat<N> a) { uint32_t m = 0; for (int i = 0; i < N; ++i) m |= (uint32_t(as_int(a).v[i]) >> 31) << i; return m; }

// [ch01-portable-compare]
template <int N> vbool<N> operator<(vfloat<N> a, vfloat<N> b) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] < b.v[i]; return r; }
template <int N> vbool<N> operator<=(vfloat<N> a, vfloat<N> b) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] <= b.v[i]; return r; }
template <int N> vbool<N> operator>(vfloat<N> a, vfloat<N> b) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] > b.v[i]; return r; }
template <int N> vbool<N> operator>=(vfloat<N> a, vfloat<N> b) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] >= b.v[i]; return r; }
template <int N> vbool<N> operator==(vfloat<N> a, vfloat<N> b) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] == b.v[i]; return r; }
/// Unordered: true where either lane is NaN.
template <int N> vbool<N> operator!=(vfloat<N> a, vfloat<N> b) { vbool<N> r; for (int i = 0; i < N; ++i) r.v[i] = a.v[i] != b.v[i]; return r; }
/// Lane i of `t` where the mask is set, of `f` where not.
template <int N> vfloat<N> select(vbool<N> m, vfloat<N> t, vfloat<N> f) { vfloat<N> r; for (int i = 0; i < N; ++i) r.v[i] = m.v[i] ? t.v[i] : f.v[i]; return r; }
// [ch01-portable-compare]
template <int N> vbool<N> isnan(vfloat<N> a) { return a != a; }

/// Float to int, truncating toward zero (cvttps2dq); NaN and out-of-range values give INT_MIN.
template <int N> vint<N> to_int_trunc(vfloat<N> a) {
  vint<N> r;
  for (int i = 0; i < N; ++i) {
    const float x = a.v[i];
    r.v[i] = (x >= -2147483648.0f && x < 2147483648.0f) ? int32_t(x) : std::numeric_limits<int32_t>::min();
  }
  return r;
}
/// Float to int, rounding to nearest even (cvtps2dq); NaN and out-of-range give INT_MIN.
template <int N> vint<N> to_int_round(vfloat<N> a) {
  vint<N> r;
  for (int i = 0; i < N; ++i) {
    const float x = std::nearbyint(a.v[i]);
    r.v[i] = (x >= -2147483648.0f && x < 2147483648.0f) ? int32_t(x) : std::numeric_limits<int32_t>::min();
  }
  return r;
}
/// Int to float, rounding to nearest even (cvtdq2ps).
template <int N> vfloat<N> to_float(vint<N> a) { vfloat<N> r; for (int i = 0; i < N; ++i) r.v[i] = float(a.v[i]); return r; }

// [ch01-portable-reduce]
/// Horizontal reductions in halving order: lane i meets lane i + N/2, then the halves halve.
template <int N, class Op> float reduce_halving(vfloat<N> a, Op op) {
  for (int width = N / 2; width >= 1; width /= 2)
    for (int i = 0; i < width; ++i) a.v[i] = op(a.v[i], a.v[i + width]);
  return a.v[0];
}
template <int N> float reduce_add(vfloat<N> a) { return reduce_halving(a, [](float x, float y) { return x + y; }); }
template <int N> float reduce_min(vfloat<N> a) { return reduce_halving(a, [](float x, float y) { return x < y ? x : y; }); }
template <int N> float reduce_max(vfloat<N> a) { return reduce_halving(a, [](float x, float y) { return x > y ? x : y; }); }
/// The lowest lane that holds the minimum (0 if every lane is NaN).
template <int N> int min_index(vfloat<N> a) {
  const uint32_t m = movemask(a == vfloat<N>(reduce_min(a)));
  return m ? bit_scan_forward(m) : 0;
}
// [ch01-portable-reduce]

/// Within each group of four lanes, lane j takes lane (i0, i1, i2, i3)[j] of that group
/// (shufps with one source; AVX shuffles work per 128-bit half in the same way).
template <int i0, int i1, int i2, int i3, int N> vfloat<N> shuffle(vfloat<N> a) {
  static_assert(N % 4 == 0, "shuffle works on groups of four lanes");
  static_assert(0 <= (i0 | i1 | i2 | i3) && (i0 | i1 | i2 | i3) < 4, "shuffle: lanes 0 to 3");
  vfloat<N> r;
  for (int g = 0; g < N; g += 4) {
    r.v[g + 0] = a.v[g + i0];
    r.v[g + 1] = a.v[g + i1];
    r.v[g + 2] = a.v[g + i2];
    r.v[g + 3] = a.v[g + i3];
  }
  return r;
}
/// Every lane takes lane i.
template <int i, int N> vfloat<N> broadcast_lane(vfloat<N> a) {
  static_assert(0 <= i && i < N, "broadcast_lane: no such lane");
  return vfloat<N>(a.v[i]);
}

}  // namespace rtk::RTK_ISA
