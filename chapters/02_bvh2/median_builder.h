/// \file
/// The chapter's simple builder: object-median splits on the longest centroid axis. It makes
/// balanced trees quickly and without any cost model; chapter 4's SAH builder replaces it.
#pragma once

#include <span>

#include "02_bvh2/build_tree.h"

namespace rtk {

/// Builds a tree of nodes with up to N children over `refs`, top down. Each node starts as one
/// child holding all of its references and is filled by repeatedly splitting its largest child
/// (the one with the most references) at the object median of the longest axis of its centroid
/// box, while that child holds more than `max_leaf_size` references and the node has room.
/// Children that end up with at most `max_leaf_size` references become leaves. Every box in the
/// tree is the exact union of the boxes below it. References that are not buildable
/// (is_buildable) are left out. The result depends only on the input, never on timing.
///
/// Throws std::invalid_argument when `max_leaf_size` is below 1.
template <int N>
BuildTree<N> build_median(std::span<const PrimRef> refs, int max_leaf_size);

extern template BuildTree<2> build_median<2>(std::span<const PrimRef>, int);
extern template BuildTree<4> build_median<4>(std::span<const PrimRef>, int);
extern template BuildTree<8> build_median<8>(std::span<const PrimRef>, int);
extern template BuildTree<16> build_median<16>(std::span<const PrimRef>, int);

}  // namespace rtk
