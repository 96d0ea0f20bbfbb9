/// \file
/// Spatial splits: a plane cuts the node's space, and every reference that straddles it is
/// clipped into a left and a right reference (Stich, Friedrich and Dietrich, "Spatial Splits in
/// Bounding Volume Hierarchies", HPG 2009). Two ways to choose the plane: the centre of each
/// axis of the node's box (Embree 1.1 guide, section 4.3.2) and SBVH's spatial bins.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "01_base/triangle_mesh.h"
#include "02_bvh2/build_tree.h"

namespace rtk::spatial {

/// A spatial split plane and what its two sides are expected to hold.
struct SpatialSplit {
  int axis = -1;  ///< -1: no plane separates anything
  float pos = 0.0f;
  /// The SAH intersection term, half_area(left) * tests(left) + half_area(right) * tests(right),
  /// a side's tests being leaf_tests(count, leaf_block) (chapter 2).
  double cost = std::numeric_limits<double>::infinity();
  uint32_t left_count = 0, right_count = 0;  ///< straddling references count on both sides
  Box3f left_bounds, right_bounds;           ///< the clipped references' bounds on each side

  bool valid() const { return axis >= 0; }
  /// The references the split adds to a set of `n`.
  size_t duplicates(size_t n) const { return size_t(left_count) + right_count - n; }
};

/// The guide's spatial split: on each axis the plane through the centre of `bounds` (the
/// references' box), priced by clipping every straddling reference. Returns every plane that
/// leaves references on both sides (at most three), axis by axis. A side is priced by its area
/// times its leaf tests in blocks of `leaf_block`, like chapter 4's object splits.
std::vector<SpatialSplit> find_centre_splits(std::span<const PrimRef> refs, const Box3f& bounds,
                                             const TriangleMesh& mesh, int leaf_block = 1);

/// SBVH's binned spatial split: `bins` equal slabs per axis over `bounds`, every reference
/// chopped exactly into the slabs it spans, entry and exit counters per slab, and a sweep over
/// the planes between slabs. Returns every plane that leaves references on both sides, axis by
/// axis and left to right, priced as find_centre_splits() prices them.
std::vector<SpatialSplit> find_binned_splits(std::span<const PrimRef> refs, const Box3f& bounds,
                                             const TriangleMesh& mesh, int bins,
                                             int leaf_block = 1);

/// The cheapest of `planes` (the first among equals) that adds at most `budget` references to a
/// set of `n`, or an invalid split.
SpatialSplit cheapest_within(const std::vector<SpatialSplit>& planes, size_t n, size_t budget);

/// The two sides of an executed spatial split.
struct SplitResult {
  std::vector<PrimRef> left, right;  ///< the references of each side, clipped where they were cut
  size_t unsplit = 0;  ///< straddling references that went wholly to one side
};

/// Sends every reference to the side of `split`'s plane it lies on, and clips the ones that
/// straddle it; with `unsplit`, a straddling reference goes wholly to one side when the SAH
/// estimated from `split`'s bounds and counts says that is cheaper (Stich et al., section 4.3).
/// The order of the input is kept on each side.
SplitResult execute_spatial_split(std::span<const PrimRef> refs, const SpatialSplit& split,
                                  const TriangleMesh& mesh, bool unsplit);

}  // namespace rtk::spatial
