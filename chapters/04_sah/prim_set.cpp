#include "04_sah/prim_set.h"

#include <limits>
#include <memory>
#include <stdexcept>

#include "04_sah/partition.h"

namespace rtk::sah {

// [ch04-leaf-test]
void evaluate(PrimSet& set, const Bins& bins, const BinMapping& map,
              const SahBuildOptions& options) {
  const uint32_t n = set.size();
  set.split = n > 1 ? find_best_split(bins, map, options.leaf_block) : Split{};
  const double area = half_area(set.bounds);
  if (n <= 1) {
    set.wants_split = false;
  } else if (!set.split.valid()) {
    // Nothing to bin by: only the leaf size limit forces a (fallback) split, done last.
    set.wants_split = n > uint32_t(options.max_leaf_size);
    set.gain = -std::numeric_limits<double>::infinity();
  } else {
    const double tests = leaf_tests(n, options.leaf_block);
    const double leaf = double(options.intersection_cost) * area * tests;
    const double split =
        double(options.traversal_cost) * area + double(options.intersection_cost) * set.split.cost;
    set.wants_split = n > uint32_t(options.max_leaf_size) || split < leaf;
    // Splits made only to fill a free slot: no extra block without a large gain.
    set.gain = slot_fill_gain(area * tests - set.split.cost, area * tests, n, set.split.left_count,
                              n - set.split.left_count, options.leaf_block);
  }
}
// [ch04-leaf-test]

PrimSet make_root_set(PrimRef* refs, uint32_t count, const Box3f& bounds, const Box3f& centroids,
                      const SahBuildOptions& options) {
  PrimSet set;
  set.end = count;
  set.bounds = bounds;
  set.centroids = centroids;
  const BinMapping map(centroids, bins_for(count, options.bins));
  auto bins = std::make_unique_for_overwrite<Bins>();
  bins->reset(map.num_bins);
  if (count >= kLargeJobPrims)
    parallel_bin_prims(refs, count, map, *bins, binning_isa(options));
  else
    bin_prims(refs, count, map, *bins, binning_isa(options));
  evaluate(set, *bins, map, options);
  return set;
}

namespace {

/// Bins a half made by a fallback split: its centroid bounds are not known yet, so a first pass
/// finds them and a second one bins. This happens only when binning failed, which is rare.
PrimSet fallback_half(PrimRef* refs, uint32_t begin, uint32_t end, const SahBuildOptions& options) {
  PrimSet half;
  half.begin = begin;
  half.end = end;
  for (uint32_t i = begin; i < end; ++i) {
    half.bounds.extend(refs[i].box());
    half.centroids.extend(centroid(refs[i]));
  }
  const BinMapping map(half.centroids, bins_for(half.size(), options.bins));
  Bins bins;
  bins.reset(map.num_bins);
  bin_prims(refs + begin, half.size(), map, bins, binning_isa(options));
  evaluate(half, bins, map, options);
  return half;
}

}  // namespace

// [ch04-split-set]
std::pair<PrimSet, PrimSet> split_set(const PrimSet& set, PrimRef* refs,
                                      const SahBuildOptions& options, bool& fallback) {
  fallback = !set.split.valid();
  if (fallback) {
    const uint32_t mid = set.begin + set.size() / 2;
    return {fallback_half(refs, set.begin, mid, options),
            fallback_half(refs, mid, set.end, options)};
  }
  // The children's bins are laid over their centroid bounds, which the parent's bins gave.
  const Split& s = set.split;
  const uint32_t right_count = set.size() - s.left_count;
  const BinMapping parent_map(set.centroids, bins_for(set.size(), options.bins));
  const BinMapping left_map(s.left_centroids, bins_for(s.left_count, options.bins));
  const BinMapping right_map(s.right_centroids, bins_for(right_count, options.bins));
  Bins left_bins, right_bins;
  const SplitPlane plane{&parent_map, s.axis, s.pos};
  const ChildBins out{&left_map, &left_bins, &right_map, &right_bins};
  const Isa isa = binning_isa(options);
  uint32_t left_count;
  if (set.size() >= kLargeJobPrims) {
    left_count = parallel_partition_and_bin(refs + set.begin, set.size(), plane, out, isa);
  } else {
    left_bins.reset(left_map.num_bins);
    right_bins.reset(right_map.num_bins);
    left_count = partition_and_bin(refs + set.begin, set.size(), plane, out, isa);
  }
  // Binning and partitioning classify with the same function, so the counts agree; if they
  // did not, the children's boxes would not bound their primitives.
  if (left_count != s.left_count)
    throw std::logic_error("split_set: partition disagrees with the bins");

  PrimSet left, right;
  left.begin = set.begin;
  left.end = right.begin = set.begin + s.left_count;
  right.end = set.end;
  left.bounds = s.left_bounds;
  left.centroids = s.left_centroids;
  right.bounds = s.right_bounds;
  right.centroids = s.right_centroids;
  evaluate(left, left_bins, left_map, options);
  evaluate(right, right_bins, right_map, options);
  return {left, right};
}
// [ch04-split-set]

}  // namespace rtk::sah
