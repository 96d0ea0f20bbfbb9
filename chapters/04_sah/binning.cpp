#include "04_sah/binning.h"

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
  for (int i = first; i < last; ++i) a.extend(bins.bin[axis][i].lower, bins.bin[axis][i].upper);
  return a.box();
}

Box3f bin_centroid_bounds(const Bins& bins, int axis, int first, int last) {
  Accumulator a;
  for (int i = first; i < last; ++i)
    a.extend(bins.bin[axis][i].cent_lower, bins.bin[axis][i].cent_upper);
  return a.box();
}

uint32_t bin_count(const Bins& bins, int axis, int first, int last) {
  uint32_t count = 0;
  for (int i = first; i < last; ++i) count += bins.count[axis][i];
  return count;
}

// [ch04-sweep]
Split find_best_split(const Bins& bins, const BinMapping& map) {
  const int n = bins.num_bins;
  Split best;
  for (int axis = 0; axis < 3; ++axis) {
    if (!map.splittable(axis)) continue;
    const Bin* bin = bins.bin[axis];
    const uint32_t* count = bins.count[axis];
    // Sweep from the right: right_cost[i] prices bins [i, n) as one child, area times count.
    double right_cost[kMaxSahBins];
    Accumulator right;
    uint32_t right_count = 0;
    for (int i = n - 1; i > 0; --i) {
      right.extend(bin[i].lower, bin[i].upper);
      right_count += count[i];
      right_cost[i] = right_count ? right.half_area() * right_count : -1.0;  // -1: nothing there
    }
    // Sweep from the left, pricing the border before each bin i.
    Accumulator left;
    uint32_t left_count = 0;
    for (int i = 1; i < n; ++i) {
      left.extend(bin[i - 1].lower, bin[i - 1].upper);
      left_count += count[i - 1];
      if (left_count == 0 || right_cost[i] < 0.0) continue;
      const double cost = left.half_area() * left_count + right_cost[i];
      if (cost < best.cost) {
        best.axis = axis;
        best.pos = i;
        best.cost = cost;
        best.left_count = left_count;
      }
    }
  }
  if (best.valid()) {
    best.left_bounds = bin_bounds(bins, best.axis, 0, best.pos);
    best.right_bounds = bin_bounds(bins, best.axis, best.pos, n);
    best.left_centroids = bin_centroid_bounds(bins, best.axis, 0, best.pos);
    best.right_centroids = bin_centroid_bounds(bins, best.axis, best.pos, n);
  }
  return best;
}
// [ch04-sweep]

}  // namespace rtk::sah
