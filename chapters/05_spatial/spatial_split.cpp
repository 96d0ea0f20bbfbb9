#include "05_spatial/spatial_split.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "04_sah/binning.h"
#include "05_spatial/clip.h"
#include "05_spatial/spatial_options.h"

namespace rtk::spatial {

namespace {

using sah::half_area;

/// The triangle a reference points to, clipped to the reference's box cut at a plane.
std::pair<Box3f, Box3f> split_ref(const PrimRef& ref, const TriangleMesh& mesh, int axis, float pos) {
  return split_triangle_box(mesh.vertex(ref.prim, 0), mesh.vertex(ref.prim, 1),
                            mesh.vertex(ref.prim, 2), ref.box(), axis, pos);
}

/// Runs body(first, last) over [0, n): serially for a small range, else as a parallel loop over
/// fixed blocks whose results the caller merges in block order (`block` names the block).
template <class Body>
void for_blocks(size_t n, const Body& body) {
  const size_t block = kPartitionBlockPrims;
  const size_t blocks = (n + block - 1) / block;
  if (n < kSpatialLargeJobRefs) {
    body(size_t(0), size_t(0), n);
    return;
  }
  tbb::parallel_for(size_t(0), blocks,
                    [&](size_t b) { body(b, b * block, std::min(n, (b + 1) * block)); });
}

size_t block_count(size_t n) {
  return n < kSpatialLargeJobRefs ? 1 : (n + kPartitionBlockPrims - 1) / kPartitionBlockPrims;
}

/// What one plane collects: the clipped bounds and counts of its two sides.
struct PlaneSides {
  Box3f left, right;
  uint32_t left_count = 0, right_count = 0;
  void merge(const PlaneSides& o) {
    left.extend(o.left), right.extend(o.right);
    left_count += o.left_count, right_count += o.right_count;
  }
};

// [ch05-spatial-bins]
/// The slabs of one axis: plane(i) is the border between slab i - 1 and slab i, computed in
/// double from the box and rounded once, so that binning and the split use the same float.
/// The borders are computed when the slabs are made: every reference looks several of them up.
struct Slabs {
  double origin = 0, width = 0, per_width = 0;
  int count = 0;
  bool usable = false;
  std::array<float, kMaxSpatialBins + 1> borders;  ///< plane(0) ... plane(count)

  Slabs(const Box3f& bounds, int axis, int bins) : count(bins) {
    origin = bounds.lower[axis];
    width = (double(bounds.upper[axis]) - origin) / bins;
    per_width = 1.0 / width;
    usable = width > 0.0 && std::isfinite(width);
    borders[0] = bounds.lower[axis], borders[size_t(bins)] = bounds.upper[axis];
    for (int i = 1; i < bins; ++i) borders[size_t(i)] = float(origin + width * i);
  }
  float plane(int i) const { return borders[size_t(std::clamp(i, 0, count))]; }
  /// The planes strictly inside slabs [f, l]: plane(f + 1) ... plane(l).
  std::span<const float> planes_within(int f, int l) const {
    return {borders.data() + f + 1, size_t(l - f)};
  }
  /// The first slab a reference counts in: the lowest i whose right plane the reference's lower
  /// end lies below (or, for a reference flat in that plane, touches). Then a reference is on
  /// the left of plane i, wholly or in part, exactly when first < i.
  int first(float lo, float hi) const {
    int i = std::clamp(int((double(lo) - origin) * per_width), 0, count - 1);  // a guess
    auto left_of = [&](int j) { return j >= count - 1 || lo < plane(j + 1) || hi <= plane(j + 1); };
    while (i > 0 && left_of(i - 1)) --i;
    while (!left_of(i)) ++i;
    return i;
  }
  /// The last slab: the highest i whose left plane the upper end lies above. A reference is on
  /// the right of plane i exactly when last >= i.
  int last(float hi) const {
    int i = std::clamp(int((double(hi) - origin) * per_width), 0, count - 1);  // a guess
    auto right_of = [&](int j) { return j <= 0 || hi > plane(j); };
    while (i < count - 1 && right_of(i + 1)) ++i;
    while (!right_of(i)) --i;
    return i;
  }
};

/// Per slab: the exact bounds of the pieces chopped into it (rounded to floats once, for the
/// sweep), and how many references enter (have their first slab) and exit (their last slab)
/// there.
struct SpatialBins {
  std::array<std::array<ExactBox, kMaxSpatialBins>, 3> bounds;
  std::array<std::array<uint32_t, kMaxSpatialBins>, 3> entry{}, exit{};

  void merge(const SpatialBins& o, int bins) {
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < bins; ++i) {
        bounds[a][i].extend(o.bounds[a][i]);
        entry[a][i] += o.entry[a][i], exit[a][i] += o.exit[a][i];
      }
  }
};

/// Chops the references [first, last) into the slabs of every usable axis.
void bin_refs(const PrimRef* refs, size_t first, size_t last, const std::array<Slabs, 3>& slabs,
              const TriangleMesh& mesh, SpatialBins& out) {
  for (size_t r = first; r < last; ++r) {
    const PrimRef& ref = refs[r];
    const Box3f box = ref.box();
    // The first and last slab on each axis; a reference within one slab counts there as it is.
    std::array<int, 3> f{}, l{};
    bool crosses = false;
    for (int axis = 0; axis < 3; ++axis) {
      const Slabs& s = slabs[axis];
      if (!s.usable) continue;
      f[axis] = s.first(box.lower[axis], box.upper[axis]), l[axis] = s.last(box.upper[axis]);
      ++out.entry[axis][f[axis]], ++out.exit[axis][l[axis]];
      if (f[axis] >= l[axis])
        out.bounds[axis][f[axis]].extend(box);
      else
        crosses = true;
    }
    if (!crosses) continue;
    // Reference chopping: the exact part of the triangle in each slab it crosses, the triangle
    // clipped to the reference's box once for every axis that chops it.
    const ClippedTriangle part(mesh.vertex(ref.prim, 0), mesh.vertex(ref.prim, 1), mesh.vertex(ref.prim, 2), box);
    for (int axis = 0; axis < 3; ++axis)
      if (slabs[axis].usable && f[axis] < l[axis])
        part.chop(axis, slabs[axis].planes_within(f[axis], l[axis]),
                  std::span<ExactBox>(out.bounds[axis].data() + f[axis], size_t(l[axis] - f[axis] + 1)));
  }
}
// [ch05-spatial-bins]

/// Prices splitting at `pos` on `axis`: both sides' counts and clipped bounds.
void price_plane(const PrimRef* refs, size_t first, size_t last, int axis, float pos,
                 const TriangleMesh& mesh, PlaneSides& out) {
  for (size_t r = first; r < last; ++r) {
    const PrimRef& ref = refs[r];
    if (ref.upper[axis] <= pos) {
      out.left.extend(ref.box()), ++out.left_count;
    } else if (ref.lower[axis] >= pos) {
      out.right.extend(ref.box()), ++out.right_count;
    } else {
      const auto [l, rr] = split_ref(ref, mesh, axis, pos);
      if (!l.empty()) out.left.extend(l), ++out.left_count;
      if (!rr.empty()) out.right.extend(rr), ++out.right_count;
      if (l.empty() && rr.empty()) out.left.extend(ref.box()), ++out.left_count;  // as executed
    }
  }
}

void consider(std::vector<SpatialSplit>& planes, int axis, float pos, const Box3f& left,
              uint32_t nl, const Box3f& right, uint32_t nr, int leaf_block) {
  if (nl == 0 || nr == 0) return;
  SpatialSplit s;
  s.axis = axis, s.pos = pos;
  s.cost =
      half_area(left) * leaf_tests(nl, leaf_block) + half_area(right) * leaf_tests(nr, leaf_block);
  s.left_count = nl, s.right_count = nr;
  s.left_bounds = left, s.right_bounds = right;
  planes.push_back(s);
}

}  // namespace

// [ch05-centre-split]
std::vector<SpatialSplit> find_centre_splits(std::span<const PrimRef> refs, const Box3f& bounds,
                                             const TriangleMesh& mesh, int leaf_block) {
  std::vector<SpatialSplit> best;
  for (int axis = 0; axis < 3; ++axis) {
    const float pos = float(0.5 * double(bounds.lower[axis]) + 0.5 * double(bounds.upper[axis]));
    if (!(bounds.lower[axis] < pos && pos < bounds.upper[axis])) continue;
    std::vector<PlaneSides> parts(block_count(refs.size()));
    for_blocks(refs.size(), [&](size_t b, size_t first, size_t last) {
      price_plane(refs.data(), first, last, axis, pos, mesh, parts[b]);
    });
    for (size_t b = 1; b < parts.size(); ++b) parts[0].merge(parts[b]);
    consider(best, axis, pos, parts[0].left, parts[0].left_count, parts[0].right,
             parts[0].right_count, leaf_block);
  }
  return best;
}
// [ch05-centre-split]

// [ch05-binned-sweep]
std::vector<SpatialSplit> find_binned_splits(std::span<const PrimRef> refs, const Box3f& bounds,
                                             const TriangleMesh& mesh, int bins, int leaf_block) {
  bins = std::clamp(bins, 2, kMaxSpatialBins);
  const std::array<Slabs, 3> slabs = {Slabs(bounds, 0, bins), Slabs(bounds, 1, bins),
                                      Slabs(bounds, 2, bins)};
  std::vector<SpatialBins> parts(block_count(refs.size()));
  for_blocks(refs.size(), [&](size_t b, size_t first, size_t last) {
    bin_refs(refs.data(), first, last, slabs, mesh, parts[b]);
  });
  for (size_t b = 1; b < parts.size(); ++b) parts[0].merge(parts[b], bins);
  const SpatialBins& sb = parts[0];

  std::vector<SpatialSplit> best;
  for (int axis = 0; axis < 3; ++axis) {
    if (!slabs[axis].usable) continue;
    // Each slab's bounds rounded once, for all the pieces in it.
    std::array<Box3f, kMaxSpatialBins> slab_bounds;
    for (int i = 0; i < bins; ++i) slab_bounds[i] = sb.bounds[axis][i].rounded();
    // Sweep from the right: bounds and exit counts of slabs [i, bins).
    std::array<Box3f, kMaxSpatialBins> right_bounds;
    std::array<uint32_t, kMaxSpatialBins> right_count;
    Box3f r;
    uint32_t nr = 0;
    for (int i = bins - 1; i > 0; --i) {
      r.extend(slab_bounds[i]), nr += sb.exit[axis][i];
      right_bounds[i] = r, right_count[i] = nr;
    }
    // Sweep from the left: bounds and entry counts of slabs [0, i), pricing plane i.
    Box3f l;
    uint32_t nl = 0;
    for (int i = 1; i < bins; ++i) {
      l.extend(slab_bounds[i - 1]), nl += sb.entry[axis][i - 1];
      const float pos = slabs[axis].plane(i);
      if (!(bounds.lower[axis] < pos && pos < bounds.upper[axis])) continue;
      consider(best, axis, pos, intersection(l, bounds), nl, intersection(right_bounds[i], bounds),
               right_count[i], leaf_block);
    }
  }
  return best;
}
// [ch05-binned-sweep]

SpatialSplit cheapest_within(const std::vector<SpatialSplit>& planes, size_t n, size_t budget) {
  SpatialSplit best;
  for (const SpatialSplit& s : planes)
    if (s.duplicates(n) <= budget && s.cost < best.cost) best = s;
  return best;
}

// [ch05-unsplit]
SplitResult execute_spatial_split(std::span<const PrimRef> refs, const SpatialSplit& split,
                                  const TriangleMesh& mesh, bool unsplit) {
  const int axis = split.axis;
  const float pos = split.pos;
  const double al = half_area(split.left_bounds), ar = half_area(split.right_bounds);
  const double nl = split.left_count, nr = split.right_count;
  const double c_split = al * nl + ar * nr;
  std::vector<SplitResult> parts(block_count(refs.size()));
  for_blocks(refs.size(), [&](size_t b, size_t first, size_t last) {
    SplitResult& out = parts[b];
    for (size_t i = first; i < last; ++i) {
      const PrimRef& ref = refs[i];
      if (ref.upper[axis] <= pos) {
        out.left.push_back(ref);
        continue;
      }
      if (ref.lower[axis] >= pos) {
        out.right.push_back(ref);
        continue;
      }
      if (unsplit) {
        // Keeping the whole reference on one side removes it from the other's count and grows
        // this side's box by it; the split's own bounds and counts are the estimate.
        const Box3f box = ref.box();
        const double c_left = half_area(merge(split.left_bounds, box)) * nl + ar * (nr - 1);
        const double c_right = al * (nl - 1) + half_area(merge(split.right_bounds, box)) * nr;
        if (c_left < c_split && c_left <= c_right) {
          out.left.push_back(ref), ++out.unsplit;
          continue;
        }
        if (c_right < c_split) {
          out.right.push_back(ref), ++out.unsplit;
          continue;
        }
      }
      const auto [l, r] = split_ref(ref, mesh, axis, pos);
      if (!l.empty()) out.left.push_back(PrimRef(l, ref.prim));
      if (!r.empty()) out.right.push_back(PrimRef(r, ref.prim));
      if (l.empty() && r.empty()) out.left.push_back(ref);  // rounding lost it: keep it whole
    }
  });
  for (size_t b = 1; b < parts.size(); ++b) {
    parts[0].left.insert(parts[0].left.end(), parts[b].left.begin(), parts[b].left.end());
    parts[0].right.insert(parts[0].right.end(), parts[b].right.begin(), parts[b].right.end());
    parts[0].unsplit += parts[b].unsplit;
  }
  return std::move(parts[0]);
}
// [ch05-unsplit]

}  // namespace rtk::spatial
