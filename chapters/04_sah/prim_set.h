/// \file
/// A set of primitives as the builder carries it from split to split: its range of the
/// builder's array, its bounds, its best binned split, and whether the SAH wants it split.
#pragma once

#include <cstdint>
#include <utility>

#include "04_sah/binning.h"
#include "04_sah/sah_options.h"

namespace rtk::sah {

/// Primitives [begin, end) of the builder's array, evaluated: a set always arrives with its
/// best split already chosen, because its bins were filled by the pass that made it.
struct PrimSet {
  uint32_t begin = 0, end = 0;
  Box3f bounds;     ///< the primitives' boxes
  Box3f centroids;  ///< their centroids
  Split split;      ///< the best binned split (invalid when binning cannot separate anything)
  /// Whether this set becomes an inner node: it holds more than max_leaf_size primitives, or the
  /// SAH prices a split below a leaf.
  bool wants_split = false;
  /// How much the SAH falls (in units of half area) when the set is split inside its parent's
  /// node, where the split costs no extra traversal step: the leaf term minus the split's
  /// intersection term. Node filling splits the child with the largest gain first.
  double gain = 0.0;

  uint32_t size() const { return end - begin; }
  /// Whether binning found a split at all.
  bool splittable() const { return split.valid(); }
};

/// Chooses a set's split from its bins and decides leaf or node (the SAH leaf test).
void evaluate(PrimSet& set, const Bins& bins, const BinMapping& map,
              const SahBuildOptions& options);

/// The root set: bins all primitives (in parallel for a large set) and evaluates them.
PrimSet make_root_set(PrimRef* refs, uint32_t count, const Box3f& bounds, const Box3f& centroids,
                      const SahBuildOptions& options);

/// Splits an evaluated set in one pass over its primitives (a parallel one for a large set) and
/// returns its two halves, evaluated. A set that binning cannot separate (all centroids equal)
/// is cut in the middle of its range; `fallback` is then set to true.
std::pair<PrimSet, PrimSet> split_set(const PrimSet& set, PrimRef* refs,
                                      const SahBuildOptions& options, bool& fallback);

}  // namespace rtk::sah
