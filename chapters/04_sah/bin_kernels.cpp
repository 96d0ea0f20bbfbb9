// The binning passes of bin_kernels.h, compiled once per ISA (namespace rtk::RTK_ISA).
#include "04_sah/bin_kernels.h"

#include <limits>
#include <utility>

#include "01_base/simd.h"

namespace rtk::RTK_ISA {

namespace {

using sah::Bin;
using sah::BinMapping;
using sah::Bins;
using sah::PrimLanes;

constexpr float kInf = std::numeric_limits<float>::infinity();

// [ch04-grow-bin]
/// How many floats of a bin one minimum grows: eight where the ISA has 256-bit registers, a
/// whole box or a whole centroid bound; four otherwise.
constexpr int kGrowWidth = kNativeWidth >= 8 ? 8 : 4;

/// A primitive as the bins take it, in Bin's layout: its box (lower corner, negated upper
/// corner) and its centroid twice (as is, negated), eight floats each, in registers of
/// W floats (kGrowWidth). Lane 3 of the lower corner, the bin's count, is +infinity: a
/// minimum then gives the bin's lane back, and the count is added to it afterwards. It is made
/// once and grows three bins.
template <int W>
struct BinEntry {
  static constexpr int kParts = 8 / W;
  vfloat<W> box[kParts], centroid[kParts];

  RTK_INLINE explicit BinEntry(const PrimLanes& p) {
    const vint<4> count_lane = select(vint<4>::iota() == vint<4>(3), vint<4>(0x7F800000), vint<4>(0));
    const vfloat<4> lower = as_float(as_int(lanes(p.lower)) | count_lane);
    const vfloat<4> neg_upper = -lanes(p.upper), c = lanes(p.centroid);
    if constexpr (W == 8) {
      box[0] = vfloat<8>(lower, neg_upper);
      centroid[0] = vfloat<8>(c, -c);
    } else {
      box[0] = lower, box[1] = neg_upper;
      centroid[0] = c, centroid[1] = -c;
    }
  }

 private:
  RTK_INLINE static vfloat<4> lanes(const sah::Lanes4& x) {
    return vfloat<4>::loadu(reinterpret_cast<const float*>(&x));
  }
};

/// Grows bin `b` by a primitive: every bound is a minimum (Bin keeps the upper corners negated),
/// kGrowWidth floats at a time, and the count in lane 3 goes up by one, an integer addition
/// in the register that holds the lower corner. The primitive is the first operand, as in a
/// minimum's rule for equal values, the one that gives the bin its own value back (its +inf
/// gives back the count). The loads and stores do not ask for alignment: a Bin is aligned to
/// its cache line, but containers are free to place Bins otherwise, and on aligned data the
/// unaligned forms cost nothing more.
RTK_INLINE void grow(Bin& b, const BinEntry<kGrowWidth>& e, vint<kGrowWidth> one_in_lane3) {
  float* box = reinterpret_cast<float*>(&b.lower);
  float* centroid = reinterpret_cast<float*>(&b.cent_lower);
  using V = vfloat<kGrowWidth>;
  for (int k = 0; k < BinEntry<kGrowWidth>::kParts; ++k) {
    V grown = min(e.box[k], V::loadu(box + k * kGrowWidth));
    if (k == 0) grown = as_float(as_int(grown) + one_in_lane3);
    grown.storeu(box + k * kGrowWidth);
    min(e.centroid[k], V::loadu(centroid + k * kGrowWidth)).storeu(centroid + k * kGrowWidth);
  }
}

/// Drops a primitive into its bin on each axis.
RTK_INLINE void add(Bins& bins, const PrimLanes& p, const BinMapping& map) {
  using VI = vint<kGrowWidth>;
  const VI one_in_lane3 = select(VI::iota() == VI(3), VI(1), VI(0));
  const sah::Ints4 i = map.bins(p.centroid);
  const BinEntry<kGrowWidth> e(p);
  grow(bins.bin[0][i[0]], e, one_in_lane3);
  grow(bins.bin[1][i[1]], e, one_in_lane3);
  grow(bins.bin[2][i[2]], e, one_in_lane3);
}
// [ch04-grow-bin]

}  // namespace

void bin_prims(const PrimRef* refs, uint32_t count, const BinMapping& map, Bins& bins) {
  for (uint32_t i = 0; i < count; ++i) add(bins, PrimLanes(refs[i]), map);
}

// [ch04-partition]
uint32_t partition_and_bin(PrimRef* refs, uint32_t count, const sah::SplitPlane& plane,
                           const sah::ChildBins& out) {
  // Hoare's partition: walk in from both ends, bin every primitive on the side it belongs to,
  // and swap the pairs found on the wrong sides.
  // Each primitive is read into lanes once; the two that stop the scans are binned from the
  // lanes already read when they are swapped. The children's mappings are copied first: the
  // bins are stored as floats, which the compiler must assume may be the mappings' floats, and
  // it would otherwise read the mappings again after every store to a bin.
  // A primitive goes left when its centroid lies below the plane's limit on the split axis
  // (SplitPlane::left_limit()): the other lanes of `limit` are -infinity, below which nothing
  // lies.
  const BinMapping left_map = *out.left_map, right_map = *out.right_map;
  alignas(16) float limit_lanes[4] = {-kInf, -kInf, -kInf, -kInf};
  limit_lanes[plane.axis] = plane.left_limit();
  const vfloat<4> limit = vfloat<4>::load(limit_lanes);
  const auto below_limit = [&limit](const PrimLanes& p) {
    return any(vfloat<4>::loadu(reinterpret_cast<const float*>(&p.centroid)) < limit);
  };
  Bins& left = *out.left;
  Bins& right = *out.right;
  uint32_t i = 0, j = count;
  while (true) {
    for (; i < j; ++i) {
      const PrimLanes p(refs[i]);
      if (!below_limit(p)) break;
      add(left, p, left_map);
    }
    if (i == j) return i;
    const PrimLanes goes_right(refs[i]);
    for (; i < j - 1; --j) {
      const PrimLanes p(refs[j - 1]);
      if (below_limit(p)) break;
      add(right, p, right_map);
    }
    if (i == j - 1) {  // refs[i] was the last one: it goes right
      add(right, goes_right, right_map);
      return i;
    }
    // refs[i] belongs right and refs[j - 1] left, and i < j - 1.
    const PrimLanes goes_left(refs[j - 1]);
    std::swap(refs[i], refs[j - 1]);
    add(left, goes_left, left_map);
    add(right, goes_right, right_map);
    ++i;
    --j;
  }
}
// [ch04-partition]

}  // namespace rtk::RTK_ISA
