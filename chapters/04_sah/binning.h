/// \file
/// Binning: the surface area heuristic evaluated at the borders of a fixed number of bins per
/// axis instead of at every primitive (Wald, "On fast construction of SAH-based bounding volume
/// hierarchies", IEEE Symposium on Interactive Ray Tracing 2007). A pass over the primitives
/// drops each centroid into one bin per axis; a sweep over the bins then prices every border.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>

#include "01_base/box3.h"
#include "01_base/platform.h"
#include "02_bvh2/build_tree.h"
#include "04_sah/sah_options.h"

namespace rtk::sah {

/// The centroid of a primitive's box, as 0.5 lower + 0.5 upper: the sum lower + upper would
/// overflow to infinity for coordinates near the largest float.
RTK_INLINE Vec3f centroid(const PrimRef& ref) { return ref.lower * 0.5f + ref.upper * 0.5f; }

/// Half the surface area of a box in double precision (zero for an empty box): in float the
/// area overflows once coordinates pass about 1e19.
inline double half_area(const Box3f& box) {
  if (box.empty()) return 0.0;
  const double dx = double(box.upper.x) - box.lower.x, dy = double(box.upper.y) - box.lower.y,
               dz = double(box.upper.z) - box.lower.z;
  return dx * dy + dy * dz + dz * dx;
}

// [ch04-bins-for]
/// How many bins a set of `prims` primitives gets: the requested number, but no more than
/// 4 + prims / 4, and at least 2. Most sets the builder prices are small (the number of sets
/// doubles at each level), and a sweep over 32 bins for a few dozen primitives is mostly over
/// empty bins. A quarter of a bin per primitive (Embree uses a twentieth) left the SAH of the
/// real meshes' trees within 0.05 % and took a third of the sweeps' instructions away.
inline int bins_for(uint32_t prims, int requested) {
  return int(std::clamp<uint32_t>(std::min(prims, 4 + prims / 4), 2u, uint32_t(requested)));
}
// [ch04-bins-for]

/// Four floats in one SSE register. The builder is compiled once, for the baseline instruction
/// set, and this GCC/Clang vector type gives it 4-wide minimum and maximum there (SSE2 on
/// x86-64) without ISA flags. Lane 3 is unused.
typedef float Lanes4 __attribute__((vector_size(16)));

/// Minimum and maximum with the SSE rule (`a < b ? a : b`), lane by lane.
RTK_INLINE Lanes4 min4(Lanes4 a, Lanes4 b) { return a < b ? a : b; }
RTK_INLINE Lanes4 max4(Lanes4 a, Lanes4 b) { return a > b ? a : b; }

/// Four 32-bit integers, the bin indices of one centroid on the three axes.
typedef int32_t Ints4 __attribute__((vector_size(16)));

/// A primitive's box corners as lanes, with zero in lane 3 (the ID's bits there could be a
/// denormal float, which arithmetic handles slowly). Each is one aligned 16-byte load and a
/// mask.
RTK_INLINE Lanes4 lanes_xyz(const void* four_words) {
  Ints4 bits;
  std::memcpy(&bits, four_words, sizeof bits);
  const Ints4 xyz{-1, -1, -1, 0};
  return reinterpret_cast<Lanes4>(bits & xyz);
}
RTK_INLINE Lanes4 lanes_lower(const PrimRef& r) { return lanes_xyz(&r.lower); }  // and the ID
RTK_INLINE Lanes4 lanes_upper(const PrimRef& r) { return lanes_xyz(&r.upper); }  // and a spare word

/// A primitive as the binning passes read it: its box corners and centroid as lanes.
struct PrimLanes {
  Lanes4 lower, upper, centroid;
  RTK_INLINE explicit PrimLanes(const PrimRef& r)
      : lower(lanes_lower(r)), upper(lanes_upper(r)), centroid(lower * 0.5f + upper * 0.5f) {}
};

// [ch04-bin-mapping]
/// Maps a centroid to its bin on each axis: bin = floor((c - origin) * scale), clamped to the
/// last bin. An axis along which the centroids do not spread (or spread so far or so little
/// that the scale is not a finite positive float) gets scale 0: binning cannot split there.
struct BinMapping {
  Lanes4 origin{0, 0, 0, 0};
  Lanes4 scale{0, 0, 0, 0};
  int num_bins = 0;

  BinMapping() = default;
  BinMapping(const Box3f& centroid_bounds, int bins) : num_bins(bins) {
    for (int axis = 0; axis < 3; ++axis) {
      const float extent = centroid_bounds.upper[axis] - centroid_bounds.lower[axis];
      const float s = float(bins) / extent;
      const bool usable = extent > 0.0f && extent <= std::numeric_limits<float>::max() &&
                          s <= std::numeric_limits<float>::max();
      origin[axis] = centroid_bounds.lower[axis];
      scale[axis] = usable ? s : 0.0f;
    }
  }
  /// Whether binning can separate anything along `axis`.
  bool splittable(int axis) const { return scale[axis] > 0.0f; }
  /// The bins of a centroid on the three axes (lane 3 is 0). The position is clamped to
  /// [0, last bin] while still a float, one minimum and one maximum (SSE2 has no integer
  /// ones); a NaN (an unusable axis, whose product may be 0 times infinity) becomes 0.
  RTK_INLINE Ints4 bins(Lanes4 c) const {
    const Lanes4 zero{0, 0, 0, 0}, last = zero + float(num_bins - 1);
    return __builtin_convertvector(min4(max4((c - origin) * scale, zero), last), Ints4);
  }
  /// The bin of a centroid's coordinate `c` along a splittable `axis`: the same arithmetic as
  /// bins(), so that partitioning sends every primitive where binning counted it.
  RTK_INLINE int bin(float c, int axis) const {
    const float f = (c - origin[axis]) * scale[axis], last = float(num_bins - 1);
    const float above = f > 0.0f ? f : 0.0f;
    return int(above < last ? above : last);
  }
};
// [ch04-bin-mapping]

// [ch04-bin-layout]
/// One bin: the bounds of the boxes and of the centroids that fell into it, 64 bytes (a cache
/// line). The upper corners are kept negated, -max(x) being min(-x), so that every bound grows
/// by a minimum: a box is eight consecutive floats (lower, then negated upper), which one
/// 256-bit minimum grows at once (bin_kernels.cpp). Lane 3 of `lower`, which no coordinate
/// uses, holds the bin's count: its bits as an integer are kCountBase plus the count. The pass
/// that grows the box adds one to those bits with an integer addition in the same register,
/// so that counting costs no memory access of its own. The base is the bits of 1.0f, which
/// keeps the lane a normal float (until a billion primitives fall into one bin): the float
/// operations that read whole registers, minimums and the sweep's areas, ignore the lane's
/// value but would slow down on a subnormal one. Plain data without constructors, so that a
/// Bins object costs nothing until reset() touches the bins in use.
struct alignas(64) Bin {
  static constexpr uint32_t kCountBase = std::bit_cast<uint32_t>(1.0f);
  Lanes4 lower, neg_upper;            ///< bounds of the primitives' boxes; lower[3]: the count
  Lanes4 cent_lower, neg_cent_upper;  ///< bounds of their centroids

  /// How many primitives fell into the bin.
  uint32_t count() const { return std::bit_cast<uint32_t>(lower[3]) - kCountBase; }
  /// Sets the count; lower[3] is written nowhere else but by the binning passes' additions.
  void set_count(uint32_t n) { lower[3] = std::bit_cast<float>(kCountBase + n); }
};
static_assert(sizeof(Bin) == 64, "one bin per cache line");
// [ch04-bin-layout]

// [ch04-bins]
/// The bins of one set of primitives on all three axes. Each bin keeps its centroids' bounds as
/// well as its boxes' bounds: once a split is chosen, the children's centroid bounds, which
/// the children's own bins need, are known without another pass over the primitives. The
/// passes that fill the bins are compiled for each instruction set (bin_kernels.h).
struct Bins {
  int num_bins = 0;
  Bin bin[3][kMaxSahBins];

  /// Empties the first `n` bins on every axis.
  void reset(int n) {
    num_bins = n;
    // An empty bin, its count (0) in lane 3 from the start: one copy per bin, not a copy and
    // then a store of the count into the lane.
    constexpr float f = std::numeric_limits<float>::infinity();
    const Lanes4 inf{f, f, f, f};
    const Lanes4 inf_and_no_count{f, f, f, std::bit_cast<float>(Bin::kCountBase)};
    const Bin empty{inf_and_no_count, inf, inf, inf};
    for (int axis = 0; axis < 3; ++axis)
      for (int i = 0; i < n; ++i) bin[axis][i] = empty;
  }
  /// Adds another set's bins (same mapping) to these. Minimum and integer addition do not
  /// depend on the order they are applied in, so the merged bins are the same whichever
  /// thread binned which primitives.
  void merge(const Bins& other) {
    for (int axis = 0; axis < 3; ++axis)
      for (int i = 0; i < num_bins; ++i) {
        const Bin& o = other.bin[axis][i];
        Bin& b = bin[axis][i];
        const uint32_t count = b.count() + o.count();
        b.lower = min4(o.lower, b.lower);
        b.neg_upper = min4(o.neg_upper, b.neg_upper);
        b.cent_lower = min4(o.cent_lower, b.cent_lower);
        b.neg_cent_upper = min4(o.neg_cent_upper, b.neg_cent_upper);
        b.set_count(count);
      }
  }
};
// [ch04-bins]

/// The box bounds of bins [first, last) on `axis`.
Box3f bin_bounds(const Bins& bins, int axis, int first, int last);
/// The centroid bounds of bins [first, last) on `axis`.
Box3f bin_centroid_bounds(const Bins& bins, int axis, int first, int last);
/// How many primitives fell into bins [first, last) on `axis`.
uint32_t bin_count(const Bins& bins, int axis, int first, int last);

/// The best binned split of a set: primitives whose bin on `axis` is below `pos` go left.
struct Split {
  int axis = -1;  ///< -1: binning found no border with primitives on both sides
  int pos = 0;
  /// The split's intersection term, area(left) * tests(left) + area(right) * tests(right), in
  /// half areas (multiply by the intersection cost for the SAH); a side's tests are its count,
  /// or its blocks when leaves test several primitives at once (SahBuildOptions::leaf_block).
  double cost = std::numeric_limits<double>::infinity();
  uint32_t left_count = 0;
  Box3f left_bounds, right_bounds;        ///< the children's boxes
  Box3f left_centroids, right_centroids;  ///< the children's centroid bounds

  bool valid() const { return axis >= 0; }
};

/// Prices every bin border on every splittable axis and returns the cheapest, the first one
/// (lowest axis, then lowest border) among equals, so that the choice is reproducible. Each
/// side is priced by its area times leaf_tests(count, leaf_block).
Split find_best_split(const Bins& bins, const BinMapping& map, int leaf_block = 1);

/// Where to cut a set: primitives whose bin on `axis` under `map` is below `pos` go left.
struct SplitPlane {
  const BinMapping* map = nullptr;
  int axis = 0;
  int pos = 0;

  // [ch04-left-limit]
  /// The least float whose bin on `axis` is `pos` or above. A bin never falls as the
  /// coordinate grows: a subtraction, a product by a positive scale, a clamp and a truncation
  /// each keep the order of their operands, rounding included. So a primitive goes left exactly
  /// when its centroid's coordinate lies below this limit, and the partition asks one
  /// comparison instead of a bin's arithmetic. The plane's own border, origin + pos / scale,
  /// lands within a few floats of the limit; a walk float by float finds it.
  float left_limit() const;
  // [ch04-left-limit]

  /// Whether `ref` goes left, by its centroid's bin on `axis` (the partition's kernels compare
  /// with left_limit() instead, which decides the same).
  RTK_INLINE bool goes_left(const PrimRef& ref) const {
    float lo[3], hi[3];
    std::memcpy(lo, &ref.lower, sizeof lo);
    std::memcpy(hi, &ref.upper, sizeof hi);
    return map->bin(lo[axis] * 0.5f + hi[axis] * 0.5f, axis) <
           pos;  // the centroid, as in centroid()
  }
};

/// Where the two halves of a split are binned: each side's mapping (made from its centroid
/// bounds, known from the parent's bins) and the bins it fills.
struct ChildBins {
  const BinMapping* left_map = nullptr;
  Bins* left = nullptr;
  const BinMapping* right_map = nullptr;
  Bins* right = nullptr;
};

}  // namespace rtk::sah
