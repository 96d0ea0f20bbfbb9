/// \file
/// The wrappers' operations one at a time, over arrays, for every ISA and width: the table
/// through which the tests (never compiled per ISA) hold each backend against the scalar one.
///
/// Inputs and outputs are 32-bit words, read as floats or as integers as the operation needs,
/// so that one set of inputs serves every operation and results compare bit for bit. The
/// arrays are processed one vector (of the given width) at a time: vector k covers the words
/// [k W, k W + W) of every array.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string_view>

#include "01_base/isa_dispatch.h"

namespace rtk {

/// One operation of the SIMD wrappers, applied to vectors a, b and c (the words of the three
/// input arrays) to give the output vector. Where an operation needs a scalar, it takes lane 0
/// of a vector: a0, b0, c0. Mask results are written as 0 or 1 per lane; operations that give
/// one value per vector (reductions, movemask, any) write it into every lane.
enum class SimdOp : uint8_t {
  // vfloat, lane by lane
  f_load_store,    ///< store(load(a)), aligned
  f_loadu_storeu,  ///< storeu(loadu(a)) at an address that is not 16-byte aligned
  f_broadcast,     ///< vfloat(a0)
  f_lane_access,   ///< lane i is a[i] through operator[]
  f_neg, f_abs, f_signmask, f_sqrt, f_floor, f_ceil, f_rcp_fast, f_rcp,
  f_add, f_sub, f_mul, f_div,
  f_add_assign, f_sub_assign, f_mul_assign, f_div_assign,  ///< a op= b
  f_min, f_max, f_xorsign, f_copysign,
  f_fmadd, f_fmsub, f_fnmadd, f_fnmsub,  ///< f(a, b, c)
  f_select,                              ///< select(from_bits(c0), a, b)
  f_shuffle_3210, f_shuffle_1032, f_shuffle_2031, f_shuffle_0000,
  f_broadcast_lane0, f_broadcast_lane3, f_broadcast_lane_last,
  f_gather,  ///< gather(a, b & (n - 1)): the whole array a is the table; n a power of two
  // vfloat compares, giving masks
  f_lt, f_le, f_gt, f_ge, f_eq, f_ne, f_isnan,
  // conversions
  f_to_int_trunc, f_to_int_round, f_as_int, i_to_float, i_as_float,
  // vfloat, one value per vector
  f_reduce_add, f_reduce_min, f_reduce_max, f_min_index, f_sign_bits,
  // vint
  i_load_store, i_loadu_storeu, i_broadcast, i_lane_access, i_iota,
  i_add, i_sub, i_mul, i_and, i_or, i_xor,
  i_shl, i_sra, i_srl,  ///< a shifted by b0 & 31
  i_min, i_max, i_eq, i_ne, i_lt, i_gt,
  i_select,  ///< select(from_bits(c0), a, b)
  i_reduce_add, i_reduce_min, i_reduce_max,
  // vbool, on the masks from_bits(a0) and from_bits(b0)
  b_from_bits, b_constant /* vbool(bool(a0 & 1)) */, b_lane_access, b_and, b_or, b_xor, b_not,
  b_movemask, b_any, b_all, b_none,
  count  ///< the number of operations
};

/// The operations' names, in the enum's order (for test messages).
inline constexpr std::string_view kSimdOpNames[] = {
    "f_load_store", "f_loadu_storeu", "f_broadcast", "f_lane_access",
    "f_neg", "f_abs", "f_signmask", "f_sqrt", "f_floor", "f_ceil", "f_rcp_fast", "f_rcp",
    "f_add", "f_sub", "f_mul", "f_div",
    "f_add_assign", "f_sub_assign", "f_mul_assign", "f_div_assign",
    "f_min", "f_max", "f_xorsign", "f_copysign",
    "f_fmadd", "f_fmsub", "f_fnmadd", "f_fnmsub",
    "f_select",
    "f_shuffle_3210", "f_shuffle_1032", "f_shuffle_2031", "f_shuffle_0000",
    "f_broadcast_lane0", "f_broadcast_lane3", "f_broadcast_lane_last",
    "f_gather",
    "f_lt", "f_le", "f_gt", "f_ge", "f_eq", "f_ne", "f_isnan",
    "f_to_int_trunc", "f_to_int_round", "f_as_int", "i_to_float", "i_as_float",
    "f_reduce_add", "f_reduce_min", "f_reduce_max", "f_min_index", "f_sign_bits",
    "i_load_store", "i_loadu_storeu", "i_broadcast", "i_lane_access", "i_iota",
    "i_add", "i_sub", "i_mul", "i_and", "i_or", "i_xor",
    "i_shl", "i_sra", "i_srl",
    "i_min", "i_max", "i_eq", "i_ne", "i_lt", "i_gt",
    "i_select",
    "i_reduce_add", "i_reduce_min", "i_reduce_max",
    "b_from_bits", "b_constant", "b_lane_access", "b_and", "b_or", "b_xor", "b_not",
    "b_movemask", "b_any", "b_all", "b_none",
};
static_assert(std::size(kSimdOpNames) == size_t(SimdOp::count), "one name per operation");

/// The name of an operation.
inline std::string_view simd_op_name(SimdOp op) { return kSimdOpNames[size_t(op)]; }

/// The SIMD widths the self-test table is compiled for.
inline constexpr int kSimdOpWidths[] = {4, 8, 16};

// Applies `op` to the n words of a, b and c, vector by vector, writing n words to `out`.
// Throws std::invalid_argument for a width other than 4, 8 or 16, an n that is not a multiple
// of the width, a null array, an unknown op, or, for f_gather, an n that is not a power of two.
RTK_DECLARE_FOR_EACH_ISA(void apply_simd_op(SimdOp op, int width, const uint32_t* a,
                                            const uint32_t* b, const uint32_t* c, uint32_t* out,
                                            size_t n))

/// The three ways to a reciprocal that the wrappers offer, from exact to fastest.
enum class Reciprocal : uint8_t {
  divide,    ///< 1 / a, correctly rounded
  rcp,       ///< the estimate refined by one Newton-Raphson step (error below 2^-21)
  rcp_fast,  ///< the hardware estimate (error below 1.5 * 2^-12)
};

// Writes out[i] = the reciprocal of in[i] by `method`, `width` floats at a time (unaligned
// loads and stores), for speed against accuracy. Throws std::invalid_argument for a width
// other than 4, 8 or 16, an n that is not a multiple of it, or null arrays.
RTK_DECLARE_FOR_EACH_ISA(void reciprocal_array(Reciprocal method, int width, const float* in,
                                               float* out, size_t n))

// The widest float vector the ISA holds in one register (1 for the scalar variant).
RTK_DECLARE_FOR_EACH_ISA(int simd_native_width())

}  // namespace rtk
