#include "04_sah/binning.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rtk::sah {

namespace {

/// A box being grown bin by bin, in the bins' lane layout.
struct Accumulator {
  static constexpr float kInf = std::numeric_limits<float>::infinity();
  Lanes4 lower{kInf, kInf, kInf, kInf};
  Lanes4 upper{-kInf, -kInf, -kInf, -kInf};

  void extend(Lanes4 lo, Lanes4 hi) {
    lower = min4(lo, lower);
    upper = max4(hi, upper);
  }
  /// Half the area in double precision (float overflows for extents past 1e19); only called
  /// on a box that holds something.
  double half_area() const {
    const double dx = double(upper[0]) - lower[0], dy = double(upper[1]) - lower[1],
                 dz = double(upper[2]) - lower[2];
    return dx * dy + dy * dz + dz * dx;
  }
  Box3f box() const { return {{lower[0], lower[1], lower[2]}, {upper[0], upper[1], upper[2]}}; }
};

}  // namespace

Box3f bin_bounds(const Bins& bins, int axis, int first, int last) {
  Accumulator a;
  for (int i = first; i < last; ++i) a.extend(bins.bin[axis][i].lower, -bins.bin[axis][i].neg_upper);
  return a.box();
}

Box3f bin_centroid_bounds(const Bins& bins, int axis, int first, int last) {
  Accumulator a;
  for (int i = first; i < last; ++i)
    a.extend(bins.bin[axis][i].cent_lower, -bins.bin[axis][i].neg_cent_upper);
  return a.box();
}

uint32_t bin_count(const Bins& bins, int axis, int first, int last) {
  uint32_t count = 0;
  for (int i = first; i < last; ++i) count += bins.bin[axis][i].count();
  return count;
}

// [ch04-sweep]
Split find_best_split(const Bins& bins, const BinMapping& map, int leaf_block) {
  const int n = bins.num_bins;
  constexpr float inf = std::numeric_limits<float>::infinity();
  const Lanes4 pos_inf{inf, inf, inf, inf}, neg_inf = -pos_inf;
  // The sweep runs in single precision, the three axes side by side in the lanes of one
  // register. Float areas overflow past coordinates of about 1e19, so the coordinates are first
  // scaled by a power of two that brings the largest to [0.5, 1): exact, and it leaves the
  // order of the costs as it was. Every primitive is in one bin of axis 0, so those bins give
  // the set's box.
  Lanes4 lo = pos_inf, hi = neg_inf;
  for (int i = 0; i < n; ++i) lo = min4(lo, bins.bin[0][i].lower), hi = max4(hi, -bins.bin[0][i].neg_upper);
  float largest = 0.0f;
  for (int a = 0; a < 3; ++a)
    if (lo[a] <= hi[a]) largest = std::max({largest, std::fabs(lo[a]), std::fabs(hi[a])});
  // Below 2^40 (the usual case) area times count stays far from overflow without scaling.
  int exponent = 0;
  if (!(largest < 0x1p40f)) std::frexp(largest, &exponent);
  const float s = exponent == 0 ? 1.0f : std::ldexp(1.0f, -std::clamp(exponent, -125, 127));
  // Counts convert to float as signed integers (SSE2 has no unsigned conversion). A set of
  // 2^31 primitives or more (64 GiB of references) would be priced wrongly, and get a poorer
  // split, never a wrong tree: the chosen split's count and cost are exact below.
  typedef uint32_t Counts4 __attribute__((vector_size(16)));
  const Counts4 none{0, 0, 0, 0};
  // A side of c primitives costs ceil(c / leaf_block) tests: (c + leaf_block - 1) >> shift.
  const int shift = std::countr_zero(unsigned(leaf_block));
  const Counts4 round_up = none + uint32_t(leaf_block - 1);
  auto tests = [&](Counts4 c) {
    return __builtin_convertvector(reinterpret_cast<Ints4>((c + round_up) >> shift), Lanes4);
  };
  // The sweeps read the bins transposed: row k of `lower` holds coordinate k of the three
  // axes' bins side by side (lane a: the bin of axis a), and row 3 their counts, which lane 3
  // of each lower corner holds; the same for the negated upper corners. Then one minimum per
  // row grows the three axes' boxes at once, and each box's extents, products and sums are
  // plain lane-by-lane operations, where the bins as stored (one axis's box per register) would
  // need shuffles at every border. Lane 3 repeats axis 2; it is never chosen (map.scale's lane
  // 3 is 0). Scaling, where needed, is applied once here: a product by a power of two keeps
  // the order of the coordinates, so the running minimums of the scaled rows are the scaled
  // minimums, bit for bit.
  struct Rows {
    Lanes4 lower[3], neg_upper[3];
    Counts4 count;
  };
  Rows rows[kMaxSahBins];
  const Lanes4 scale{s, s, s, s};
  auto transpose = [](const Lanes4 (&r)[3], Lanes4 (&out)[3]) {
    const Lanes4 xy = __builtin_shufflevector(r[0], r[1], 0, 4, 1, 5);  // x0 x1 y0 y1
    const Lanes4 zc = __builtin_shufflevector(r[0], r[1], 2, 6, 3, 7);  // z0 z1 c0 c1
    out[0] = __builtin_shufflevector(xy, r[2], 0, 1, 4, 4);
    out[1] = __builtin_shufflevector(xy, r[2], 2, 3, 5, 5);
    out[2] = __builtin_shufflevector(zc, r[2], 0, 1, 6, 6);
    return __builtin_shufflevector(zc, r[2], 2, 3, 7, 7);
  };
  const Counts4 count_base = none + Bin::kCountBase;
  for (int i = 0; i < n; ++i) {
    const Lanes4 lower[3] = {bins.bin[0][i].lower, bins.bin[1][i].lower, bins.bin[2][i].lower};
    const Lanes4 neg_upper[3] = {bins.bin[0][i].neg_upper, bins.bin[1][i].neg_upper, bins.bin[2][i].neg_upper};
    rows[i].count = reinterpret_cast<Counts4>(transpose(lower, rows[i].lower)) - count_base;
    transpose(neg_upper, rows[i].neg_upper);
    if (s != 1.0f)
      for (int k = 0; k < 3; ++k) rows[i].lower[k] *= scale, rows[i].neg_upper[k] *= scale;
  }
  // A growing box of each axis, and its price: half its area, (dx dy + dy dz) + dz dx, times
  // its tests. The extents come out negated, -(upper - lower) = neg_upper + lower exactly, and
  // the products of two of them are the products of the extents.
  struct Growing {
    Lanes4 lower[3], neg_upper[3];
    Counts4 count;
    void grow(const Rows& r) {
      for (int k = 0; k < 3; ++k) lower[k] = min4(lower[k], r.lower[k]), neg_upper[k] = min4(neg_upper[k], r.neg_upper[k]);
      count += r.count;
    }
    Lanes4 half_area() const {
      const Lanes4 dx = neg_upper[0] + lower[0], dy = neg_upper[1] + lower[1], dz = neg_upper[2] + lower[2];
      return (dx * dy + dy * dz) + dz * dx;
    }
  };
  const Growing empty{{pos_inf, pos_inf, pos_inf}, {pos_inf, pos_inf, pos_inf}, none};
  // Sweep from the right: right_cost[i] prices bins [i, n) of each axis as one child, area
  // times tests (infinite where no primitive is there).
  Lanes4 right_cost[kMaxSahBins];
  {
    Growing g = empty;
    for (int i = n - 1; i > 0; --i) {
      g.grow(rows[i]);
      right_cost[i] = g.count == none ? pos_inf : g.half_area() * tests(g.count);
    }
  }
  // Sweep from the left, pricing the border before each bin i, and keep the cheapest: the
  // first one, lowest axis then lowest border, among equals.
  Lanes4 cost[kMaxSahBins];
  {
    Growing g = empty;
    for (int i = 1; i < n; ++i) {
      g.grow(rows[i - 1]);
      cost[i] = g.count == none ? pos_inf : g.half_area() * tests(g.count) + right_cost[i];
    }
  }
  // The cheapest border of every axis at once, lane by lane, without a branch on which is
  // cheaper (a running minimum's branch goes wrong whenever a new minimum turns up). The
  // minimum keeps its running value against a NaN cost, as a comparison would.
  Lanes4 lowest = pos_inf;
  for (int i = 1; i < n; ++i) lowest = min4(cost[i], lowest);
  const Lanes4 zero{0, 0, 0, 0};
  lowest = map.scale > zero ? lowest : pos_inf;  // splittable(), lane by lane; lane 3 is out too
  // The lowest axis among equals, then its first border among equals.
  Split best;
  float best_cost = inf;
  for (int axis = 0; axis < 3; ++axis)
    if (lowest[axis] < best_cost) best_cost = lowest[axis], best.axis = axis;
  if (best.valid()) {
    best.pos = 1;
    while (!(cost[best.pos][best.axis] == best_cost)) ++best.pos;
    best.left_count = bin_count(bins, best.axis, 0, best.pos);
    best.left_bounds = bin_bounds(bins, best.axis, 0, best.pos);
    best.right_bounds = bin_bounds(bins, best.axis, best.pos, n);
    best.left_centroids = bin_centroid_bounds(bins, best.axis, 0, best.pos);
    best.right_centroids = bin_centroid_bounds(bins, best.axis, best.pos, n);
    // The chosen split's price in double precision, as the leaf test compares it.
    best.cost = half_area(best.left_bounds) * leaf_tests(best.left_count, leaf_block) +
                half_area(best.right_bounds) *
                    leaf_tests(bin_count(bins, best.axis, best.pos, n), leaf_block);
  }
  return best;
}
// [ch04-sweep]

float SplitPlane::left_limit() const {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const auto at_or_above = [&](float c) { return map->bin(c, axis) >= pos; };
  const auto below = [](float c) { return std::nextafter(c, -kInf); };
  // A few steps from the border's float suffice; then the limit is t: at or above, and the
  // float below it not.
  float t = map->origin[axis] + float(pos) / map->scale[axis];
  for (int step = 0; step < 16 && std::isfinite(t); ++step) {
    if (!at_or_above(t)) t = std::nextafter(t, kInf);
    else if (at_or_above(below(t))) t = below(t);
    else return t;
  }
  // Otherwise (a border near the end of the float range) bisect the floats, ordered as integers:
  // below every float the bin is 0 < pos; at +infinity it is the last bin, >= pos.
  const auto key = [](float f) {
    const int32_t b = std::bit_cast<int32_t>(f);
    return b < 0 ? int64_t(INT32_MIN) - b : int64_t(b);
  };
  const auto value = [](int64_t k) {
    return std::bit_cast<float>(int32_t(k < 0 ? int64_t(INT32_MIN) - k : k));
  };
  int64_t lo = key(-kInf), hi = key(kInf);  // bin(lo) < pos <= bin(hi)
  while (hi - lo > 1) {
    const int64_t mid = lo + (hi - lo) / 2;
    (at_or_above(value(mid)) ? hi : lo) = mid;
  }
  return value(hi);
}

}  // namespace rtk::sah
