/// \file
/// What the spatial-split builder can be asked to do and what it reports.
#pragma once

#include <cstddef>
#include <cstdint>

#include "04_sah/sah_options.h"

namespace rtk {

/// Which spatial splits compete with the object splits.
enum class SpatialSplitMode {
  none,    ///< object splits only (chapter 4's choices)
  centre,  ///< the guide's: one plane per axis, through the centre of the node's box
  binned,  ///< SBVH: planes between spatial bins, references chopped exactly into the bins
};

// [ch05-alpha]
/// Spatial splits are tried only where the boxes of the best object split's two children overlap
/// by more than this fraction of the root's surface area (SBVH's alpha, section 4.4 of Stich et
/// al.). Near the root, where boxes are large, almost every overlap counts; deep down, small
/// overlaps are left alone, which keeps both the build time and the references in check. The
/// paper's 1e-5 is used: its figures show the tree quality flat from 1e-5 down to 0.
inline constexpr double kSpatialAlpha = 1e-5;
// [ch05-alpha]

/// Spatial bins per axis of the binned mode. Each bin a reference spans costs one exact clip, so
/// the build time grows with the bins: on sponza and the chapter's hall, 16 bins priced within
/// 0.3 % of 32 in SAH at 0.56-0.76 of the build time (chapter.md, "Measurements").
inline constexpr int kDefaultSpatialBins = 16;

/// The most spatial bins per axis the builder supports.
inline constexpr int kMaxSpatialBins = 64;

/// Sets of at least this many references are split with parallel passes (binning, chopping and
/// partitioning over fixed blocks of references, merged in block order).
inline constexpr uint32_t kSpatialLargeJobRefs = 1u << 15;

/// The knobs of build_spatial_sah().
struct SpatialBuildOptions {
  /// Bins, costs, leaf size, rotations, occluder order and threads, as for chapter 4's builder.
  SahBuildOptions sah;
  /// Which spatial splits are tried.
  SpatialSplitMode mode = SpatialSplitMode::binned;
  /// Spatial bins per axis (binned mode), 2 to kMaxSpatialBins.
  int spatial_bins = kDefaultSpatialBins;
  /// The duplication budget: extra references the tree may hold, as a fraction of the number of
  /// triangles (0.3 = at most 30 % more references than triangles). Finite, at least 0; 0 makes
  /// the same tree as chapter 4's builder.
  float budget = 0.3f;
  /// Spatial splits are priced only where the object split's children overlap by at least this
  /// fraction of the set's own surface area, besides SBVH's alpha (kSpatialAlpha). Alpha, a
  /// fraction of the root's area, lets nearly every set of a scene of long triangles be priced;
  /// this rule keeps the pricing to the sets whose object split is poor for its size, where a
  /// spatial split can win. 0 prices every set alpha passes; 1 prices (almost) none. The default
  /// is measured in chapter 5 ("Where to look for spatial splits").
  float min_overlap = 0.2f;
  /// Spatial splits are priced only for sets of at least this many full leaves of references
  /// (min_leaves * sah.max_leaf_size); smaller sets take their object split. Such a set becomes
  /// a few leaves a level or two further down, so a better plane saves little there, while
  /// pricing it costs as much per reference as near the root. 0 prices every set the other
  /// rules let through. The default is measured in chapter 5 ("Where to look for spatial
  /// splits").
  uint32_t min_leaves = 4;
  /// Reference unsplitting (Stich et al., section 4.3): a reference that straddles a spatial
  /// split plane goes wholly to one side when that is cheaper than cutting it in two.
  bool unsplit = true;
};

/// What a spatial-split build did; like chapter 4's figures, independent of the thread schedule.
struct SpatialBuildStats {
  size_t triangles = 0;       ///< buildable triangles (each is referenced at least once)
  size_t skipped = 0;         ///< triangles with NaN, infinite or inverted boxes, left out
  size_t references = 0;      ///< references in the leaves (triangles plus duplicates)
  size_t budget = 0;          ///< duplicates the budget allowed
  size_t inner_nodes = 0;     ///< nodes of the tree
  size_t leaves = 0;          ///< leaf children (including a leaf root)
  size_t spatial_searches = 0;  ///< sets whose spatial split planes were priced
  size_t object_splits = 0;   ///< binary splits made by object partitioning
  size_t spatial_splits = 0;  ///< binary splits made by a spatial plane
  size_t unsplit = 0;         ///< straddling references kept whole by unsplitting
  size_t fallback_splits = 0; ///< splits in the middle of the set: nothing else separated it
  size_t rotations = 0;       ///< tree rotations applied
  size_t breadth_first_levels = 0;  ///< levels built breadth-first before the subtree jobs
  size_t subtree_jobs = 0;    ///< subtrees built depth-first, each by one thread
};

}  // namespace rtk
