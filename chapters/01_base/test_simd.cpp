// The SIMD wrappers of every variant the machine runs, at every width, held against the scalar
// variant (the portable backend, which is the specification) on the same inputs. Not compiled
// per ISA: each variant is reached through its entry point in simd_ops.h.
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "01_base/platform.h"
#include "01_base/simd_ops.h"

using namespace rtk;

namespace {

constexpr size_t kWords = 1024;  // per input array: a power of two (the gather's table size)

uint32_t bits_of(float x) { return std::bit_cast<uint32_t>(x); }
float float_of(uint32_t w) { return std::bit_cast<float>(w); }
bool is_nan_word(uint32_t w) { return std::isnan(float_of(w)); }

// Values where the backends could differ: zeros of both signs, infinities, NaNs with several
// payloads (quiet and signalling), denormals, the extremes, halfway cases for rounding, and
// the integers and floats next to the limits of float-to-int conversion.
const std::vector<uint32_t>& special_words() {
  static const std::vector<uint32_t> words = [] {
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<uint32_t> w = {
        bits_of(0.0f), bits_of(-0.0f), bits_of(1.0f), bits_of(-1.0f), bits_of(inf), bits_of(-inf),
        0x7FC00000u, 0xFFC00000u, 0x7FC12345u, 0x7F800001u /* signalling */, 0xFFA00001u,
        0x00000001u, 0x80000001u, 0x007FFFFFu, 0x807FFFFFu, 0x00400000u,  // denormals
        bits_of(std::numeric_limits<float>::min()), bits_of(-std::numeric_limits<float>::min()),
        bits_of(std::numeric_limits<float>::max()), bits_of(-std::numeric_limits<float>::max()),
        bits_of(0.5f), bits_of(-0.5f), bits_of(1.5f), bits_of(2.5f), bits_of(-2.5f),
        bits_of(0x1.fffffep-2f) /* just below 0.5 */, bits_of(8388607.5f),
        bits_of(2147483648.0f), bits_of(-2147483648.0f), bits_of(2147483520.0f),
        bits_of(-2147483904.0f), bits_of(4294967296.0f), bits_of(1e30f), bits_of(-1e-30f),
        bits_of(0x1p125f), bits_of(0x1p126f), bits_of(0x1p-126f), bits_of(0x1p-127f),
        // as integers
        0x80000000u, 0x7FFFFFFFu, 0x80000001u, 0x7FFFFFFEu, 0xFFFFFFFFu, 2u, 3u, 31u, 32u,
        16777217u, uint32_t(-16777217), 33554435u};
    return w;
  }();
  return words;
}

struct Inputs {
  std::vector<uint32_t> a, b, c;
};

// Inputs over many magnitudes: a quarter special values, a quarter random bit patterns (every
// exponent, some NaNs), a quarter ordinary floats with some exact halves, a quarter small
// integers. b repeats a (or its negation) in some lanes, so that compares meet equality and
// pairs of zeros. The words at multiples of 4 (lane 0 of a vector at every width) are masks
// and shift counts too, so some are all ones or zero.
Inputs make_inputs(uint64_t seed) {
  std::mt19937_64 random(seed);
  const std::vector<uint32_t>& special = special_words();
  auto word = [&]() -> uint32_t {
    switch (random() % 4) {
      case 0: return special[random() % special.size()];
      case 1: return uint32_t(random());
      case 2: {
        const float x = float(int64_t(random() % 4001) - 2000) / (random() % 2 ? 8.0f : 3.0f);
        return bits_of(x);
      }
      default: return uint32_t(int32_t(random() % 2001) - 1000);
    }
  };
  Inputs in;
  for (auto* array : {&in.a, &in.b, &in.c}) {
    array->resize(kWords);
    for (uint32_t& w : *array) w = word();
  }
  for (size_t i = 0; i < kWords; ++i) {
    const uint64_t r = random() % 16;
    if (r < 2) in.b[i] = in.a[i];
    if (r == 2) in.b[i] = in.a[i] ^ 0x80000000u;
  }
  for (auto* array : {&in.a, &in.b, &in.c})
    for (size_t i = 0; i < kWords; i += 4) {
      const uint64_t r = random() % 8;
      if (r == 0) (*array)[i] = 0xFFFFFFFFu;
      if (r == 1) (*array)[i] = 0;
    }
  return in;
}

std::vector<uint32_t> run(Isa isa, SimdOp op, int width, const Inputs& in) {
  std::vector<uint32_t> out(kWords, 0xDEADBEEFu);
  RTK_PICK_ISA(isa, apply_simd_op)(op, width, in.a.data(), in.b.data(), in.c.data(), out.data(),
                                   kWords);
  return out;
}

// How an operation's results are compared.
enum class Compare {
  bits,         // bit for bit, NaN payloads included: operations that only move bits
  bits_or_nan,  // bit for bit, except that any NaN equals any NaN: arithmetic
  reciprocal,   // within the bound of rcp_fast or rcp (tested on their own below)
  fma,          // against a fused or unfused reference (tested on its own below)
};

Compare compare_of(SimdOp op) {
  switch (op) {
    // The compiler may swap the operands of + and *, and with two NaNs x86 passes on the
    // first one's payload; glibc's floorf and ceilf return a signalling NaN as it is, where
    // roundps quiets it. (-, /, sqrt and the rest agree to the last bit, NaNs included.)
    case SimdOp::f_add: case SimdOp::f_mul: case SimdOp::f_add_assign:
    case SimdOp::f_mul_assign: case SimdOp::f_reduce_add:
    case SimdOp::f_floor: case SimdOp::f_ceil:
      return Compare::bits_or_nan;
    case SimdOp::f_rcp_fast: case SimdOp::f_rcp:
      return Compare::reciprocal;
    case SimdOp::f_fmadd: case SimdOp::f_fmsub: case SimdOp::f_fnmadd: case SimdOp::f_fnmsub:
      return Compare::fma;
    default:
      return Compare::bits;
  }
}

std::string hex(uint32_t w) {
  std::ostringstream s;
  s << "0x" << std::hex << w << " (" << float_of(w) << " / " << int32_t(w) << ")";
  return s.str();
}

// Compares a variant's output with the expected one; describes the first difference.
std::string first_difference(const std::vector<uint32_t>& got, const std::vector<uint32_t>& want,
                             bool nan_equals_nan, const Inputs& in) {
  for (size_t i = 0; i < got.size(); ++i) {
    if (got[i] == want[i]) continue;
    if (nan_equals_nan && is_nan_word(got[i]) && is_nan_word(want[i])) continue;
    return "word " + std::to_string(i) + ": got " + hex(got[i]) + ", expected " + hex(want[i]) +
           "; a = " + hex(in.a[i]) + ", b = " + hex(in.b[i]) + ", c = " + hex(in.c[i]);
  }
  return "";
}

std::string variant(Isa isa, int width) {
  return std::string(isa_name(isa)) + " width " + std::to_string(width);
}

}  // namespace

TEST_CASE("ch01: each variant reports the width of its registers") {
  const int expected[] = {1, 4, 8, 16};
  for (Isa isa : supported_isas()) CHECK(RTK_PICK_ISA(isa, simd_native_width)() == expected[int(isa)]);
}

TEST_CASE("ch01: every SIMD operation of every variant and width matches the scalar variant") {
  // [ch01-test-every-op]
  for (uint64_t seed : {1u, 2u, 3u}) {
    const Inputs in = make_inputs(seed);
    for (size_t o = 0; o < size_t(SimdOp::count); ++o) {
      const SimdOp op = SimdOp(o);
      const Compare how = compare_of(op);
      if (how == Compare::reciprocal || how == Compare::fma) continue;
      for (int width : kSimdOpWidths) {
        const std::vector<uint32_t> want = run(Isa::scalar, op, width, in);
        for (Isa isa : supported_isas()) {
          INFO(simd_op_name(op), " ", variant(isa, width), " seed ", seed);
          const std::string diff =
              first_difference(run(isa, op, width, in), want, how == Compare::bits_or_nan, in);
          CHECK_MESSAGE(diff.empty(), diff);
        }
      }
    }
  }
  // [ch01-test-every-op]
}

TEST_CASE("ch01: the scalar variant follows its own rules") {
  // A few of the specification's rules, checked on the scalar variant against plain C++.
  const Inputs in = make_inputs(7);
  const std::vector<uint32_t> mins = run(Isa::scalar, SimdOp::f_min, 4, in);
  const std::vector<uint32_t> ne = run(Isa::scalar, SimdOp::f_ne, 4, in);
  const std::vector<uint32_t> trunc = run(Isa::scalar, SimdOp::f_to_int_trunc, 4, in);
  for (size_t i = 0; i < kWords; ++i) {
    const float a = float_of(in.a[i]), b = float_of(in.b[i]);
    CHECK(mins[i] == (a < b ? in.a[i] : in.b[i]));
    CHECK(ne[i] == uint32_t(std::isnan(a) || std::isnan(b) || a != b));
    if (std::isnan(a) || std::fabs(a) >= 2147483648.0f)
      CHECK(trunc[i] == 0x80000000u);
    else
      CHECK(int32_t(trunc[i]) == int32_t(a));
  }
}

TEST_CASE("ch01: fmadd is fused where the ISA has FMA, and a*b+c rounded twice on SSE4") {
  const Inputs in = make_inputs(11);
  const SimdOp ops[] = {SimdOp::f_fmadd, SimdOp::f_fmsub, SimdOp::f_fnmadd, SimdOp::f_fnmsub};
  // The references, computed here: this file is compiled without FMA and with
  // -ffp-contract=off, so a * b + c is rounded twice, and std::fma once.
  auto reference = [&](SimdOp op, bool fused) {
    std::vector<uint32_t> out(kWords);
    for (size_t i = 0; i < kWords; ++i) {
      const float a = float_of(in.a[i]), b = float_of(in.b[i]), c = float_of(in.c[i]);
      float r = 0;
      switch (op) {
        case SimdOp::f_fmadd: r = fused ? std::fma(a, b, c) : a * b + c; break;
        case SimdOp::f_fmsub: r = fused ? std::fma(a, b, -c) : a * b - c; break;
        case SimdOp::f_fnmadd: r = fused ? std::fma(-a, b, c) : c - a * b; break;
        default: r = fused ? std::fma(-a, b, -c) : -(a * b) - c; break;
      }
      out[i] = bits_of(r);
    }
    return out;
  };
  for (SimdOp op : ops) {
    const std::vector<uint32_t> fused = reference(op, true), unfused = reference(op, false);
    CHECK(fused != unfused);  // the inputs do tell the two apart
    for (Isa isa : supported_isas())
      for (int width : kSimdOpWidths) {
        // Only SSE4's own four-lane vector lacks FMA; its wider vectors are portable ones,
        // which call std::fma.
        const bool is_fused = !(isa == Isa::sse4 && width == 4);
        INFO(simd_op_name(op), " ", variant(isa, width), is_fused ? " (fused)" : " (unfused)");
        const std::string diff =
            first_difference(run(isa, op, width, in), is_fused ? fused : unfused, true, in);
        CHECK_MESSAGE(diff.empty(), diff);
      }
  }
}

TEST_CASE("ch01: rcp_fast and rcp meet their error bounds and agree on special values") {
  // Inputs over the whole domain 2^-126 <= |a| < 2^125, every exponent, random mantissas;
  // then the special values and some inputs outside the domain.
  std::mt19937_64 random(5);
  Inputs in;
  in.a.resize(kWords);
  for (size_t i = 0; i < kWords; ++i) {
    const uint32_t exponent = 1 + uint32_t(random() % 251);  // biased exponents 1 ... 251
    in.a[i] = (uint32_t(random() % 2) << 31) | (exponent << 23) | uint32_t(random() & 0x7FFFFF);
  }
  const uint32_t inf = bits_of(std::numeric_limits<float>::infinity());
  const uint32_t specials[] = {0u, 0x80000000u, inf, inf | 0x80000000u, 0x7FC00000u, 0xFFC00000u};
  const uint32_t outside[] = {0x00000001u, 0x807FFFFFu, 0x00400000u, bits_of(0x1p125f),
                              bits_of(-0x1.fffffep127f), bits_of(0x1p126f)};
  for (size_t i = 0; i < std::size(specials); ++i) in.a[i] = specials[i];
  for (size_t i = 0; i < std::size(outside); ++i) in.a[16 + i] = outside[i];
  in.b = in.c = in.a;

  struct Bound {
    SimdOp op;
    double relative;
  };
  for (const Bound bound : {Bound{SimdOp::f_rcp_fast, 1.5 * 0x1p-12}, Bound{SimdOp::f_rcp, 0x1p-21}}) {
    for (Isa isa : supported_isas())
      for (int width : kSimdOpWidths) {
        INFO(simd_op_name(bound.op), " ", variant(isa, width));
        const std::vector<uint32_t> out = run(isa, bound.op, width, in);
        double worst = 0;
        int wrong_specials = 0, wrong_signs = 0;
        for (size_t i = 0; i < kWords; ++i) {
          const float a = float_of(in.a[i]), r = float_of(out[i]);
          const float magnitude = std::fabs(a);
          if (std::isnan(a)) {
            wrong_specials += !std::isnan(r);
          } else if (magnitude == 0 || std::isinf(a)) {
            wrong_specials += out[i] != bits_of(1.0f / a);  // +-inf for +-0, +-0 for +-inf
          } else if (magnitude < 0x1p-126f || magnitude >= 0x1p125f) {
            wrong_signs += std::signbit(r) != std::signbit(a) || std::isnan(r);
          } else {
            const double exact = 1.0 / double(a);
            worst = std::max(worst, std::fabs((double(r) - exact) / exact));
          }
        }
        CHECK(wrong_specials == 0);
        CHECK(wrong_signs == 0);
        CHECK(worst < bound.relative);
      }
  }
}

TEST_CASE("ch01: reciprocal_array computes what the wrappers' reciprocals compute") {
  const Inputs in = make_inputs(17);
  std::vector<float> x(kWords), out(kWords);
  for (size_t i = 0; i < kWords; ++i) x[i] = float_of(in.a[i]);
  const Inputs one_over{std::vector<uint32_t>(kWords, bits_of(1.0f)), in.a, in.a};
  struct Case {
    Reciprocal method;
    SimdOp op;
    const Inputs* inputs;
  };
  for (const Case& c : {Case{Reciprocal::divide, SimdOp::f_div, &one_over},
                        Case{Reciprocal::rcp, SimdOp::f_rcp, &in},
                        Case{Reciprocal::rcp_fast, SimdOp::f_rcp_fast, &in}})
    for (Isa isa : supported_isas())
      for (int width : kSimdOpWidths) {
        INFO(simd_op_name(c.op), " ", variant(isa, width));
        RTK_PICK_ISA(isa, reciprocal_array)(c.method, width, x.data(), out.data(), kWords);
        std::vector<uint32_t> words(kWords);
        for (size_t i = 0; i < kWords; ++i) words[i] = bits_of(out[i]);
        const std::string diff = first_difference(words, run(isa, c.op, width, *c.inputs), false, in);
        CHECK_MESSAGE(diff.empty(), diff);
      }
  CHECK_THROWS_AS(RTK_PICK_ISA(best_isa(), reciprocal_array)(Reciprocal::rcp, 2, x.data(), out.data(), 16),
                  std::invalid_argument);
  CHECK_THROWS_AS(RTK_PICK_ISA(best_isa(), reciprocal_array)(Reciprocal(7), 4, x.data(), out.data(), 16),
                  std::invalid_argument);
}

TEST_CASE("ch01: 0 * inf makes NaN, and std::min and the wrappers' min then disagree") {
  // An axis-parallel ray (direction component 0, so 1/d = inf) whose origin lies in a box's
  // plane: (plane - origin) * (1/d) = 0 * inf = NaN.
  const float inf = std::numeric_limits<float>::infinity();
  Inputs in;
  in.a.assign(kWords, bits_of(0.0f));  // plane - origin
  in.b.assign(kWords, bits_of(inf));   // 1 / direction
  in.c.assign(kWords, bits_of(3.0f));
  for (Isa isa : supported_isas())
    for (int width : kSimdOpWidths) {
      INFO(variant(isa, width));
      const std::vector<uint32_t> t = run(isa, SimdOp::f_mul, width, in);
      REQUIRE(is_nan_word(t[0]));
      // min(NaN, 3): the wrappers return the second argument, as minps does ...
      Inputs pair{t, in.c, in.c};
      CHECK(float_of(run(isa, SimdOp::f_min, width, pair)[0]) == 3.0f);
      CHECK(float_of(run(isa, SimdOp::f_max, width, pair)[0]) == 3.0f);
      // ... and min(3, NaN) returns the NaN.
      Inputs swapped{in.c, t, in.c};
      CHECK(is_nan_word(run(isa, SimdOp::f_min, width, swapped)[0]));
    }
  // std::min(a, b) is `b < a ? b : a`: it returns its first argument, the NaN.
  const float nan = float_of(0x7FC00000u);
  CHECK(std::isnan(std::min(nan, 3.0f)));
  CHECK(std::min(3.0f, nan) == 3.0f);
}

TEST_CASE("ch01: movemask and set_bits visit the lanes of a mask in order") {
  const Inputs in = make_inputs(13);
  for (Isa isa : supported_isas())
    for (int width : kSimdOpWidths) {
      INFO(variant(isa, width));
      const std::vector<uint32_t> lt = run(isa, SimdOp::f_lt, width, in);
      Inputs as_mask = in;  // the compare's lanes, packed into a movemask word per vector
      for (size_t k = 0; k < kWords; k += size_t(width)) {
        uint32_t mask = 0;
        for (int i = 0; i < width; ++i) mask |= lt[k + i] << i;
        as_mask.a[k] = mask;
      }
      const std::vector<uint32_t> moved = run(isa, SimdOp::b_movemask, width, as_mask);
      for (size_t k = 0; k < kWords; k += size_t(width)) {
        const uint32_t mask = as_mask.a[k];
        CHECK(moved[k] == mask);  // from_bits then movemask is the identity on the low lanes
        std::vector<int> visited;
        for (int i : set_bits(mask)) visited.push_back(i);
        CHECK(int(visited.size()) == pop_count(mask));
        CHECK(std::is_sorted(visited.begin(), visited.end()));
        for (int i : visited) CHECK(lt[k + size_t(i)] == 1);
        uint32_t left = mask;
        for (int i : visited) CHECK(pop_lowest_bit(left) == i);
        CHECK(left == 0);
      }
    }
}

TEST_CASE("ch01: min_index picks the lowest of tied lanes") {
  for (Isa isa : supported_isas())
    for (int width : kSimdOpWidths) {
      INFO(variant(isa, width));
      // Vector k has every lane 7 except the minimum 1 in lanes k % W and (k + W/2 + 1) % W
      // (a tie across the halves that the halving reduction compares last), so the answer
      // is the lower of the two.
      Inputs in;
      in.a.assign(kWords, bits_of(7.0f));
      in.b = in.c = in.a;
      std::vector<uint32_t> expected(kWords);
      for (size_t k = 0; k < kWords / size_t(width); ++k) {
        const size_t first = k % size_t(width), second = (k + size_t(width) / 2 + 1) % size_t(width);
        in.a[k * size_t(width) + first] = in.a[k * size_t(width) + second] = bits_of(1.0f);
        for (int i = 0; i < width; ++i) expected[k * size_t(width) + size_t(i)] = uint32_t(std::min(first, second));
      }
      CHECK(run(isa, SimdOp::f_min_index, width, in) == expected);
      // -0 and +0 are equal: the lowest zero lane wins whichever sign the minimum has.
      in.a.assign(kWords, bits_of(0.0f));
      for (size_t k = 0; k < kWords; k += 3) in.a[k] = bits_of(-0.0f);
      for (size_t k = 0; k < kWords; k += size_t(width)) CHECK(run(isa, SimdOp::f_min_index, width, in)[k] == 0);
      // No lane is the minimum of all NaNs: the answer is lane 0.
      in.a.assign(kWords, 0x7FC00000u);
      CHECK(run(isa, SimdOp::f_min_index, width, in) == std::vector<uint32_t>(kWords, 0));
    }
}

TEST_CASE("ch01: the self-test table refuses what it cannot do") {
  const Inputs in = make_inputs(3);
  std::vector<uint32_t> out(kWords);
  for (Isa isa : supported_isas()) {
    auto apply = RTK_PICK_ISA(isa, apply_simd_op);
    CHECK_THROWS_AS(apply(SimdOp::f_add, 5, in.a.data(), in.b.data(), in.c.data(), out.data(), kWords),
                    std::invalid_argument);
    CHECK_THROWS_AS(apply(SimdOp::f_add, 8, in.a.data(), in.b.data(), in.c.data(), out.data(), 12),
                    std::invalid_argument);
    CHECK_THROWS_AS(apply(SimdOp::f_gather, 4, in.a.data(), in.b.data(), in.c.data(), out.data(), 12),
                    std::invalid_argument);
    CHECK_THROWS_AS(apply(SimdOp::count, 4, in.a.data(), in.b.data(), in.c.data(), out.data(), 16),
                    std::invalid_argument);
    CHECK_THROWS_AS(apply(SimdOp::f_add, 4, nullptr, in.b.data(), in.c.data(), out.data(), 16),
                    std::invalid_argument);
  }
}

TEST_CASE("ch01: select_bits picks the second value exactly when asked, bit for bit") {
  CHECK(rtk::select_bits(false, 7u, 9u) == 7u);
  CHECK(rtk::select_bits(true, 7u, 9u) == 9u);
  CHECK(rtk::select_bits(true, 0u, 0xffffffffu) == 0xffffffffu);
  // Floats keep their bits: a negative zero and a NaN's payload come through unchanged.
  const float nan = std::bit_cast<float>(0x7fc01234u);
  CHECK(std::bit_cast<uint32_t>(rtk::select_bits(true, 1.0f, -0.0f)) == 0x80000000u);
  CHECK(std::bit_cast<uint32_t>(rtk::select_bits(false, nan, 2.0f)) == 0x7fc01234u);
  CHECK(rtk::select_bits(false, 1.5f, -3.0f) == 1.5f);
}
