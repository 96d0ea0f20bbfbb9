// The binning passes, compiled once per instruction set (cmake/rtk_isa.cmake).
//
// A bin is 64 bytes of minimums (binning.h): lower corner, negated upper corner, centroid,
// negated centroid. A primitive is read once into the same 16 lanes, and adding it to a bin
// is then a minimum and a store per register the 16 lanes fill: one with AVX-512, two with
// AVX2, four with SSE4 and with the scalar variant (compiled for the baseline, SSE2). The
// lanes are GCC/Clang vectors of the variant's register width; the bin is always 16 floats,
// so the one source needs no width parameter.
#include "04_sah/binning_kernels.h"

#include <cstring>
#include <utility>

namespace rtk::RTK_ISA {

namespace {

using sah::Bin;
using sah::BinMapping;
using sah::Bins;

typedef float Floats4 __attribute__((vector_size(16)));
typedef int32_t Ints4 __attribute__((vector_size(16)));

/// The floats of one register: a bin is kParts of them. A vector wider than the registers
/// would be split by the compiler lane by lane, not register by register.
#if defined(__AVX512F__)
constexpr int kPartFloats = 16;
#elif defined(__AVX2__)
constexpr int kPartFloats = 8;
#else
constexpr int kPartFloats = 4;
#endif
typedef float Part __attribute__((vector_size(4 * kPartFloats)));
constexpr int kParts = 16 / kPartFloats;
static_assert(sizeof(Part) * kParts == sizeof(Bin));

/// The x, y, z lanes of four words, with zero in lane 3 (the primitive's ID or a spare word,
/// whose bits could be a denormal float, which arithmetic handles slowly).
RTK_INLINE Floats4 xyz(const void* four_words) {
  Ints4 bits;
  std::memcpy(&bits, four_words, sizeof bits);
  const Ints4 keep{-1, -1, -1, 0};
  return reinterpret_cast<Floats4>(bits & keep);
}

/// The quarters a, b, c, d (16 floats) as the registers of a bin: themselves, joined into
/// halves, or the halves joined into the whole, register inserts all.
template <int Parts>
RTK_INLINE void join(Floats4 a, Floats4 b, Floats4 c, Floats4 d, Part (&parts)[Parts]) {
  if constexpr (Parts == 4) {
    parts[0] = a, parts[1] = b, parts[2] = c, parts[3] = d;
  } else {
    const auto ab = __builtin_shufflevector(a, b, 0, 1, 2, 3, 4, 5, 6, 7);
    const auto cd = __builtin_shufflevector(c, d, 0, 1, 2, 3, 4, 5, 6, 7);
    if constexpr (Parts == 2)
      parts[0] = ab, parts[1] = cd;
    else
      parts[0] = __builtin_shufflevector(ab, cd, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  }
}

// [ch04-binned-prim]
/// A primitive as the bins take it: the 16 lanes of a bin's minimums, and its centroid, which
/// picks the bins. The centroid is 0.5 lower + 0.5 upper, as centroid() has it.
struct BinnedPrim {
  Part parts[kParts];
  Floats4 centroid;

  RTK_INLINE explicit BinnedPrim(const PrimRef& r) {
    const Floats4 lower = xyz(&r.lower), upper = xyz(&r.upper);
    centroid = lower * 0.5f + upper * 0.5f;
    join(lower, -upper, centroid, -centroid, parts);
  }
};
// [ch04-binned-prim]

/// A bin mapping as vectors, copied out of the BinMapping: the bins are stores of float
/// vectors, after each of which the compiler would otherwise read a mapping in memory again.
struct Mapping {
  Floats4 origin, scale, last;

  explicit Mapping(const BinMapping& m)
      : origin(m.origin), scale(m.scale), last(Floats4{} + float(m.num_bins - 1)) {}

  /// BinMapping::bin() on the three axes at once: floor((c - origin) * scale), clamped to
  /// [0, last] while still floats (a NaN, 0 times infinity on an unusable axis, gives 0).
  RTK_INLINE Ints4 bins(Floats4 c) const {
    const Floats4 f = (c - origin) * scale;
    const Floats4 above = f > 0.0f ? f : Floats4{};
    return __builtin_convertvector(above < last ? above : last, Ints4);
  }
};

// [ch04-bin-add]
/// Adds a primitive to its bin on each axis: a minimum per register of the bin.
RTK_INLINE void add(Bins& bins, const BinnedPrim& p, const Mapping& map) {
  const Ints4 i = map.bins(p.centroid);
  const int i0 = i[0], i1 = i[1], i2 = i[2];
  for (Bin* bin : {&bins.bin[0][i0], &bins.bin[1][i1], &bins.bin[2][i2]}) {
    char* bytes = reinterpret_cast<char*>(bin);
    for (int k = 0; k < kParts; ++k) {
      Part b;
      std::memcpy(&b, bytes + k * sizeof b, sizeof b);
      b = p.parts[k] < b ? p.parts[k] : b;
      std::memcpy(bytes + k * sizeof b, &b, sizeof b);
    }
  }
  ++bins.count[i0][0], ++bins.count[i1][1], ++bins.count[i2][2];
}
// [ch04-bin-add]

// [ch04-partition]
/// Hoare's partition along `Axis`: walk in from both ends, bin every primitive on the side it
/// belongs to, and swap the pairs found on the wrong sides. Each primitive is read once; the
/// two that stop the scans are binned from what was read when they are swapped.
template <int Axis>
uint32_t partition_along(PrimRef* refs, uint32_t count, const Mapping& parent, int pos,
                         Bins& left, const Mapping& left_map, Bins& right,
                         const Mapping& right_map) {
  auto goes_left = [&](const BinnedPrim& p) { return parent.bins(p.centroid)[Axis] < pos; };
  uint32_t i = 0, j = count;
  while (true) {
    for (; i < j; ++i) {
      const BinnedPrim p(refs[i]);
      if (!goes_left(p)) break;
      add(left, p, left_map);
    }
    if (i == j) return i;
    const BinnedPrim to_right(refs[i]);
    for (; i < j - 1; --j) {
      const BinnedPrim p(refs[j - 1]);
      if (goes_left(p)) break;
      add(right, p, right_map);
    }
    if (i == j - 1) {  // refs[i] was the last one: it goes right
      add(right, to_right, right_map);
      return i;
    }
    // refs[i] belongs right and refs[j - 1] left, and i < j - 1.
    const BinnedPrim to_left(refs[j - 1]);
    std::swap(refs[i], refs[j - 1]);
    add(left, to_left, left_map);
    add(right, to_right, right_map);
    ++i;
    --j;
  }
}
// [ch04-partition]

}  // namespace

void bin_prims(const PrimRef* refs, uint32_t count, const BinMapping& map, Bins& bins) {
  const Mapping m(map);
  for (uint32_t i = 0; i < count; ++i) add(bins, BinnedPrim(refs[i]), m);
}

uint32_t partition_and_bin(PrimRef* refs, uint32_t count, const sah::SplitPlane& plane,
                           const sah::ChildBins& out) {
  // The axis as a template argument: the lane a centroid's side is read from is then fixed.
  const Mapping parent(*plane.map), left(*out.left_map), right(*out.right_map);
  switch (plane.axis) {
    case 0: return partition_along<0>(refs, count, parent, plane.pos, *out.left, left, *out.right, right);
    case 1: return partition_along<1>(refs, count, parent, plane.pos, *out.left, left, *out.right, right);
    default: return partition_along<2>(refs, count, parent, plane.pos, *out.left, left, *out.right, right);
  }
}

}  // namespace rtk::RTK_ISA
