// The self-test table of the SIMD wrappers (simd_ops.h), compiled once per ISA: each operation
// of simd_portable.h applied vector by vector to arrays, at the widths 4, 8 and 16. In an ISA's
// copy, the widths its registers hold run the intrinsic backends; the others run the portable
// one compiled with that ISA's flags.
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "01_base/simd.h"
#include "01_base/simd_ops.h"

namespace rtk::RTK_ISA {

namespace {

// Moves words between the arrays and vectors through aligned buffers, so that the vectors are
// loaded with the aligned `load` and no float is read through an integer pointer.
template <int W>
struct Io {
  static vfloat<W> f(const uint32_t* p) {
    alignas(64) float lanes[W];
    std::memcpy(lanes, p, sizeof lanes);
    return vfloat<W>::load(lanes);
  }
  static vint<W> i(const uint32_t* p) {
    alignas(64) int32_t lanes[W];
    std::memcpy(lanes, p, sizeof lanes);
    return vint<W>::load(lanes);
  }
  static void put(uint32_t* out, vfloat<W> x) {
    alignas(64) float lanes[W];
    x.store(lanes);
    std::memcpy(out, lanes, sizeof lanes);
  }
  static void put(uint32_t* out, vint<W> x) {
    alignas(64) int32_t lanes[W];
    x.store(lanes);
    std::memcpy(out, lanes, sizeof lanes);
  }
  static void put(uint32_t* out, vbool<W> m) {
    const uint32_t bits = movemask(m);
    for (int i = 0; i < W; ++i) out[i] = (bits >> i) & 1;
  }
  static void put_word(uint32_t* out, uint32_t word) {
    for (int i = 0; i < W; ++i) out[i] = word;
  }
  static void put_float(uint32_t* out, float x) {
    uint32_t word;
    std::memcpy(&word, &x, sizeof word);
    put_word(out, word);
  }
  // Unaligned forms: the buffers are offset by one lane from a 64-byte boundary.
  static void copy_unaligned_float(const uint32_t* p, uint32_t* out) {
    alignas(64) float in_lanes[W + 1], out_lanes[W + 1];
    std::memcpy(in_lanes + 1, p, W * sizeof(float));
    vfloat<W>::loadu(in_lanes + 1).storeu(out_lanes + 1);
    std::memcpy(out, out_lanes + 1, W * sizeof(float));
  }
  static void copy_unaligned_int(const uint32_t* p, uint32_t* out) {
    alignas(64) int32_t in_lanes[W + 1], out_lanes[W + 1];
    std::memcpy(in_lanes + 1, p, W * sizeof(int32_t));
    vint<W>::loadu(in_lanes + 1).storeu(out_lanes + 1);
    std::memcpy(out, out_lanes + 1, W * sizeof(int32_t));
  }
};

template <int W>
void apply_width(SimdOp op, const uint32_t* a, const uint32_t* b, const uint32_t* c,
                 uint32_t* out, size_t n) {
  using F = vfloat<W>;
  using I = vint<W>;
  using B = vbool<W>;
  using io = Io<W>;
  std::vector<float> table;  // the gather's table: all of a, as floats
  if (op == SimdOp::f_gather) {
    table.resize(n);
    std::memcpy(table.data(), a, n * sizeof(float));
  }
  for (size_t k = 0; k < n; k += W) {
    const uint32_t *pa = a + k, *pb = b + k, *pc = c + k;
    uint32_t* o = out + k;
    const F fa = io::f(pa), fb = io::f(pb), fc = io::f(pc);
    const I ia = io::i(pa), ib = io::i(pb);
    const B ma = B::from_bits(pa[0]), mb = B::from_bits(pb[0]), mc = B::from_bits(pc[0]);
    const int count = int(pb[0] & 31);
    F acc = fa;
    switch (op) {
      case SimdOp::f_load_store: io::put(o, fa); break;
      case SimdOp::f_loadu_storeu: io::copy_unaligned_float(pa, o); break;
      case SimdOp::f_broadcast: io::put(o, F(fa[0])); break;
      case SimdOp::f_lane_access:
        for (int i = 0; i < W; ++i) {
          const float lane = fa[i];
          std::memcpy(o + i, &lane, sizeof lane);
        }
        break;
      case SimdOp::f_neg: io::put(o, -fa); break;
      case SimdOp::f_abs: io::put(o, abs(fa)); break;
      case SimdOp::f_signmask: io::put(o, signmask(fa)); break;
      case SimdOp::f_sqrt: io::put(o, sqrt(fa)); break;
      case SimdOp::f_floor: io::put(o, floor(fa)); break;
      case SimdOp::f_ceil: io::put(o, ceil(fa)); break;
      case SimdOp::f_rcp_fast: io::put(o, rcp_fast(fa)); break;
      case SimdOp::f_rcp: io::put(o, rcp(fa)); break;
      case SimdOp::f_add: io::put(o, fa + fb); break;
      case SimdOp::f_sub: io::put(o, fa - fb); break;
      case SimdOp::f_mul: io::put(o, fa * fb); break;
      case SimdOp::f_div: io::put(o, fa / fb); break;
      case SimdOp::f_add_assign: io::put(o, acc += fb); break;
      case SimdOp::f_sub_assign: io::put(o, acc -= fb); break;
      case SimdOp::f_mul_assign: io::put(o, acc *= fb); break;
      case SimdOp::f_div_assign: io::put(o, acc /= fb); break;
      case SimdOp::f_min: io::put(o, min(fa, fb)); break;
      case SimdOp::f_max: io::put(o, max(fa, fb)); break;
      case SimdOp::f_xorsign: io::put(o, xorsign(fa, fb)); break;
      case SimdOp::f_copysign: io::put(o, copysign(fa, fb)); break;
      case SimdOp::f_fmadd: io::put(o, fmadd(fa, fb, fc)); break;
      case SimdOp::f_fmsub: io::put(o, fmsub(fa, fb, fc)); break;
      case SimdOp::f_fnmadd: io::put(o, fnmadd(fa, fb, fc)); break;
      case SimdOp::f_fnmsub: io::put(o, fnmsub(fa, fb, fc)); break;
      case SimdOp::f_select: io::put(o, select(mc, fa, fb)); break;
      case SimdOp::f_shuffle_3210: io::put(o, shuffle<3, 2, 1, 0>(fa)); break;
      case SimdOp::f_shuffle_1032: io::put(o, shuffle<1, 0, 3, 2>(fa)); break;
      case SimdOp::f_shuffle_2031: io::put(o, shuffle<2, 0, 3, 1>(fa)); break;
      case SimdOp::f_shuffle_0000: io::put(o, shuffle<0, 0, 0, 0>(fa)); break;
      case SimdOp::f_broadcast_lane0: io::put(o, broadcast_lane<0>(fa)); break;
      case SimdOp::f_broadcast_lane3: io::put(o, broadcast_lane<3>(fa)); break;
      case SimdOp::f_broadcast_lane_last: io::put(o, broadcast_lane<W - 1>(fa)); break;
      case SimdOp::f_gather: io::put(o, F::gather(table.data(), ib & I(int32_t(n - 1)))); break;
      case SimdOp::f_lt: io::put(o, fa < fb); break;
      case SimdOp::f_le: io::put(o, fa <= fb); break;
      case SimdOp::f_gt: io::put(o, fa > fb); break;
      case SimdOp::f_ge: io::put(o, fa >= fb); break;
      case SimdOp::f_eq: io::put(o, fa == fb); break;
      case SimdOp::f_ne: io::put(o, fa != fb); break;
      case SimdOp::f_isnan: io::put(o, isnan(fa)); break;
      case SimdOp::f_to_int_trunc: io::put(o, to_int_trunc(fa)); break;
      case SimdOp::f_to_int_round: io::put(o, to_int_round(fa)); break;
      case SimdOp::f_as_int: io::put(o, as_int(fa)); break;
      case SimdOp::i_to_float: io::put(o, to_float(ia)); break;
      case SimdOp::i_as_float: io::put(o, as_float(ia)); break;
      case SimdOp::f_reduce_add: io::put_float(o, reduce_add(fa)); break;
      case SimdOp::f_reduce_min: io::put_float(o, reduce_min(fa)); break;
      case SimdOp::f_reduce_max: io::put_float(o, reduce_max(fa)); break;
      case SimdOp::f_min_index: io::put_word(o, uint32_t(min_index(fa))); break;
      case SimdOp::f_sign_bits: io::put_word(o, sign_bits(fa)); break;
      case SimdOp::i_load_store: io::put(o, ia); break;
      case SimdOp::i_loadu_storeu: io::copy_unaligned_int(pa, o); break;
      case SimdOp::i_broadcast: io::put(o, I(ia[0])); break;
      case SimdOp::i_lane_access:
        for (int i = 0; i < W; ++i) o[i] = uint32_t(ia[i]);
        break;
      case SimdOp::i_iota: io::put(o, I::iota()); break;
      case SimdOp::i_add: io::put(o, ia + ib); break;
      case SimdOp::i_sub: io::put(o, ia - ib); break;
      case SimdOp::i_mul: io::put(o, ia * ib); break;
      case SimdOp::i_and: io::put(o, ia & ib); break;
      case SimdOp::i_or: io::put(o, ia | ib); break;
      case SimdOp::i_xor: io::put(o, ia ^ ib); break;
      case SimdOp::i_shl: io::put(o, ia << count); break;
      case SimdOp::i_sra: io::put(o, ia >> count); break;
      case SimdOp::i_srl: io::put(o, srl(ia, count)); break;
      case SimdOp::i_min: io::put(o, min(ia, ib)); break;
      case SimdOp::i_max: io::put(o, max(ia, ib)); break;
      case SimdOp::i_eq: io::put(o, ia == ib); break;
      case SimdOp::i_ne: io::put(o, ia != ib); break;
      case SimdOp::i_lt: io::put(o, ia < ib); break;
      case SimdOp::i_gt: io::put(o, ia > ib); break;
      case SimdOp::i_select: io::put(o, select(mc, ia, ib)); break;
      case SimdOp::i_reduce_add: io::put_word(o, uint32_t(reduce_add(ia))); break;
      case SimdOp::i_reduce_min: io::put_word(o, uint32_t(reduce_min(ia))); break;
      case SimdOp::i_reduce_max: io::put_word(o, uint32_t(reduce_max(ia))); break;
      case SimdOp::b_from_bits: io::put(o, ma); break;
      case SimdOp::b_constant: io::put(o, B(bool(pa[0] & 1))); break;
      case SimdOp::b_lane_access:
        for (int i = 0; i < W; ++i) o[i] = ma[i] ? 1 : 0;
        break;
      case SimdOp::b_and: io::put(o, ma & mb); break;
      case SimdOp::b_or: io::put(o, ma | mb); break;
      case SimdOp::b_xor: io::put(o, ma ^ mb); break;
      case SimdOp::b_not: io::put(o, !ma); break;
      case SimdOp::b_movemask: io::put_word(o, movemask(ma)); break;
      case SimdOp::b_any: io::put_word(o, any(ma)); break;
      case SimdOp::b_all: io::put_word(o, all(ma)); break;
      case SimdOp::b_none: io::put_word(o, none(ma)); break;
      case SimdOp::count: break;  // refused by apply_simd_op
    }
  }
}

template <int W>
void reciprocals(Reciprocal method, const float* in, float* out, size_t n) {
  switch (method) {
    case Reciprocal::divide:
      for (size_t i = 0; i < n; i += W) (vfloat<W>(1.0f) / vfloat<W>::loadu(in + i)).storeu(out + i);
      break;
    case Reciprocal::rcp:
      for (size_t i = 0; i < n; i += W) rcp(vfloat<W>::loadu(in + i)).storeu(out + i);
      break;
    case Reciprocal::rcp_fast:
      for (size_t i = 0; i < n; i += W) rcp_fast(vfloat<W>::loadu(in + i)).storeu(out + i);
      break;
  }
}

}  // namespace

void reciprocal_array(Reciprocal method, int width, const float* in, float* out, size_t n) {
  if (width != 4 && width != 8 && width != 16)
    throw std::invalid_argument("reciprocal_array: width " + std::to_string(width) +
                                " (choose 4, 8 or 16)");
  if (n % size_t(width) != 0)
    throw std::invalid_argument("reciprocal_array: " + std::to_string(n) +
                                " floats are not a whole number of vectors");
  if (uint8_t(method) > uint8_t(Reciprocal::rcp_fast))
    throw std::invalid_argument("reciprocal_array: unknown method");
  if (n == 0) return;
  if (!in || !out) throw std::invalid_argument("reciprocal_array: null array");
  switch (width) {
    case 4: return reciprocals<4>(method, in, out, n);
    case 8: return reciprocals<8>(method, in, out, n);
    default: return reciprocals<16>(method, in, out, n);
  }
}

void apply_simd_op(SimdOp op, int width, const uint32_t* a, const uint32_t* b, const uint32_t* c,
                   uint32_t* out, size_t n) {
  if (size_t(op) >= size_t(SimdOp::count))
    throw std::invalid_argument("apply_simd_op: unknown operation " + std::to_string(int(op)));
  if (width != 4 && width != 8 && width != 16)
    throw std::invalid_argument("apply_simd_op: width " + std::to_string(width) +
                                " (the table has widths 4, 8 and 16)");
  if (n % size_t(width) != 0)
    throw std::invalid_argument("apply_simd_op: " + std::to_string(n) +
                                " words are not a whole number of vectors of width " +
                                std::to_string(width));
  if (n == 0) return;
  if (!a || !b || !c || !out) throw std::invalid_argument("apply_simd_op: null array");
  if (op == SimdOp::f_gather && (n & (n - 1)) != 0)
    throw std::invalid_argument("apply_simd_op: f_gather needs a power-of-two table size, not " +
                                std::to_string(n));
  switch (width) {
    case 4: return apply_width<4>(op, a, b, c, out, n);
    case 8: return apply_width<8>(op, a, b, c, out, n);
    default: return apply_width<16>(op, a, b, c, out, n);
  }
}

int simd_native_width() { return kNativeWidth; }

}  // namespace rtk::RTK_ISA
