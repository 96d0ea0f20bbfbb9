/// \file
/// What the binned SAH builder can be asked to do, what it reports, and the fixed constants that
/// decide how it divides its work between threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "01_base/cpu_features.h"
#include "02_bvh2/build_tree.h"

namespace rtk {

/// The most bins per axis the builder supports; the Embree 1.1 guide uses up to 32.
inline constexpr int kMaxSahBins = 64;

// [ch04-granularity]
/// Sets of at least this many primitives are "large jobs": binning and partitioning them are
/// themselves parallel loops over blocks of primitives. At the top of the tree there is one set
/// and nothing else to do, so its passes must be shared; lower down, sibling subtrees are tasks
/// that keep the threads busy, and a parallel loop would only add its overhead (bins per thread
/// to merge, a second pass to swap misplaced primitives). The root's node is filled by one split
/// after another, each waiting for the one before, and its last splits cut quarters of the scene
/// into eighths; a split below this threshold runs on one thread while the others wait, so it
/// lies well below a quarter of any scene worth building in parallel. 2^13 primitives make 4
/// blocks.
inline constexpr uint32_t kLargeJobPrims = 1u << 13;

/// Sets of fewer primitives are "small jobs": one thread builds their whole subtree without
/// creating tasks, then improves it with rotations. Such a subtree takes a millisecond or two;
/// cutting it into tasks would cost scheduling and fragments and gain nothing once every thread
/// has small jobs of its own (the guide credits this strategy with 10 % on large scenes).
/// Between the two thresholds lie "medium jobs": one thread fills the node, and each child
/// becomes a task of its own.
inline constexpr uint32_t kSmallJobPrims = 1u << 12;

/// The parallel partition of a large job cuts its range into blocks of this many primitives.
/// The blocks, not the threads, fix where every primitive ends up, so the tree does not depend
/// on how many threads took part.
inline constexpr uint32_t kPartitionBlockPrims = 1u << 11;
static_assert(kSmallJobPrims <= kLargeJobPrims, "a large job is not a small one");
static_assert(kLargeJobPrims >= 4 * kPartitionBlockPrims,
              "the smallest large job gives each of two threads two blocks");
// [ch04-granularity]

/// The node depth (the root at 1) from which an N-wide tree's nodes are filled by median splits:
/// the levels left below, at most log_N(2^32) + 1, then fit in chapter 3's 64-level traversal
/// stacks whatever the SAH did above. Chapter 5's builder keeps to the same bound.
template <int N>
inline constexpr int kMedianFillDepth = [] {
  int log2n = 0;
  while ((1 << log2n) < N) ++log2n;  // ceil(log2 N)
  return 64 - (32 + log2n - 1) / log2n - 1;
}();

/// How many bottom-up rounds of tree rotations a small job makes; a round that finds nothing to
/// improve ends them early.
inline constexpr int kRotationRounds = 3;

/// How the children of each node are ordered for occlusion rays, which stop at the first hit
/// and so gain from visiting likely blockers first (closest-hit traversal orders children by
/// distance and does not care).
enum class OccluderOrder {
  off,            ///< children stay in spatial order, left to right along the split axes
  largest_box,    ///< larger boxes first: they are entered by more rays
  likely_blocker  ///< highest odds of blocking per unit of expected work first (the chapter)
};

/// The knobs of build_binned_sah(). The defaults are those the chapter's measurements chose.
struct SahBuildOptions {
  /// Candidate split planes per axis are the borders of this many bins over the centroids'
  /// bounds, 2 to kMaxSahBins. Small sets use fewer (bins_for() in binning.h).
  int bins = 32;
  /// No leaf holds more primitives than this (at least 1). Smaller sets become leaves when
  /// the SAH says a leaf is cheaper than a split.
  int max_leaf_size = 8;
  /// The SAH cost of visiting a node (testing its children's boxes), relative to...
  float traversal_cost = 1.0f;
  /// ...the cost of intersecting one primitive. Both must be finite; this one positive. Half a
  /// node step: of the prices the chapter measured (1, 0.5, 0.25), trees built with this one
  /// traced fastest through chapter 3's BVH4 kernels.
  float intersection_cost = 0.5f;
  /// How many primitives a leaf tests at once: 1, 2, 4, 8 or 16. Chapter 6's layouts store a
  /// leaf's triangles in blocks of 4 or 8 that are tested together, so a leaf of n primitives
  /// costs ceil(n / leaf_block) tests, and `intersection_cost` is then the price of one block.
  /// With 1, a leaf costs n tests, the SAH of MacDonald and Booth.
  int leaf_block = 1;
  /// Improve small subtrees with Kensler's tree rotations (2008).
  bool rotations = true;
  /// How each node's children are ordered for occlusion rays.
  OccluderOrder occluder_order = OccluderOrder::likely_blocker;
  /// 0: run in the caller's TBB task arena (all cores unless the caller limited them);
  /// n > 0: run in a private arena of n threads. The tree is the same either way.
  int threads = 0;
  /// The variant of the binning passes (bin_kernels.h); nothing: the best the CPU runs. The
  /// tree is the same for every variant.
  std::optional<Isa> isa;
};

/// The variant of the binning passes the options ask for.
inline Isa binning_isa(const SahBuildOptions& options) { return options.isa.value_or(best_isa()); }
/// The options with the binning passes' instruction set chosen, so that a builder asks once
/// rather than at every set.
inline SahBuildOptions with_binning_isa(SahBuildOptions options) {
  options.isa = binning_isa(options);
  return options;
}

/// Options for leaves stored in blocks of `leaf_block` triangles tested together: a leaf is
/// priced by its blocks, one block at the price of a node step (intersection_cost 1), and may
/// hold two blocks (eight triangles for single triangles): the price and the size that
/// measured best for BVH8 with blocks of eight (chapter 4, "Leaves tested in blocks"). Chapter 6
/// builds each triangle layout with these, for its block width.
inline SahBuildOptions block_priced_options(int leaf_block) {
  SahBuildOptions options;
  options.leaf_block = leaf_block;
  options.intersection_cost = 1.0f;
  options.max_leaf_size = leaf_block == 1 ? 8 : 2 * leaf_block;
  return options;
}

// [ch04-slot-fill]
/// A split whose halves take more blocks than their set fills a free slot of a node only if it
/// lowers the set's intersection term by more than this share. With 0, BVH8 trees with
/// triangle8 leaves took a quarter less memory, but one mesh's shadow rays slowed by a third;
/// with a quarter, nearly the same memory without that loss (chapter 4).
inline constexpr double kBlockFillGain = 0.25;

/// The gain, for node filling (node_filling.h), of cutting a set of `n` primitives into `left`
/// and `right`: `gain`, the drop of its intersection term from `leaf_term`, the term of the set
/// as one leaf. A split made only to fill a free slot costs no traversal step, but where its
/// halves take more blocks of `leaf_block` (above 1) than the set, the slot is free and the
/// block is not: four triangles in a block of eight. Such a split keeps its gain only above
/// kBlockFillGain of the term, and gets -infinity (no filling) below.
inline double slot_fill_gain(double gain, double leaf_term, uint32_t n, uint32_t left,
                             uint32_t right, int leaf_block) {
  const bool adds_blocks =
      leaf_block > 1 &&
      leaf_tests(left, leaf_block) + leaf_tests(right, leaf_block) > leaf_tests(n, leaf_block);
  if (adds_blocks && !(gain > kBlockFillGain * leaf_term))
    return -std::numeric_limits<double>::infinity();
  return gain;
}
// [ch04-slot-fill]

/// What a build did. Every count is a property of the input and the options alone, never of
/// the thread schedule, so that two builds of one scene report the same figures.
struct SahBuildStats {
  size_t primitives = 0;       ///< primitives in the tree
  size_t skipped = 0;          ///< input references with NaN, infinite or inverted boxes, left out
  size_t inner_nodes = 0;      ///< nodes of the tree
  size_t leaves = 0;           ///< leaf children (including a leaf root)
  size_t large_jobs = 0;       ///< nodes whose splits ran as parallel loops
  size_t medium_jobs = 0;      ///< nodes filled by one thread whose children became tasks
  size_t small_jobs = 0;       ///< subtrees built by one thread from start to end
  size_t fallback_splits = 0;  ///< splits in the middle of the range: no bin could separate
  size_t rotations = 0;        ///< tree rotations applied
};

/// Throws std::invalid_argument, naming `who` and the option, unless the options are usable:
/// 2 to kMaxSahBins bins, a leaf size of at least 1, a leaf block of 1, 2, 4, 8 or 16, finite
/// costs (intersection above zero), a thread count of 0 or more. Chapter 5's builder checks its
/// SAH part with it too.
void check_sah_options(const SahBuildOptions& options, const std::string& who);

}  // namespace rtk
