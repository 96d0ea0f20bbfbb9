/// \file
/// Occluder ordering: within each node, the children most likely to stop a shadow ray come
/// first, so that occluded(), which may stop at any hit, visits them first. (Embree 1.1 sorts
/// them to the end of the node because its traversal pops the last child pushed first; here
/// the first child is visited first.)
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "02_bvh2/build_tree.h"
#include "04_sah/sah_options.h"

namespace rtk::sah {

// [ch04-occluder-score]
/// What ordering needs to know about a subtree, worked out bottom-up.
struct OccluderSummary {
  /// The chance that a shadow ray which enters the subtree's box is blocked inside it. For a
  /// leaf, the surface inside over the box's half area (Cauchy-Crofton: a random line that
  /// meets a convex box meets a flat piece of area a inside it with probability
  /// a / half-area(box)), capped at 1; the surface is estimated as half of each primitive box's
  /// half area (a flat triangle covers at most half of its box's largest face; the builder sees
  /// boxes only). For a node, one less the chance that none of the children it enters blocks
  /// it, their odds taken as independent.
  double blocks = 0.0;
  /// The expected work of a shadow ray that enters the subtree's box: its children visited in
  /// their stored order, each entered with the odds of the SAH, and the search over where one
  /// blocks the ray. A child that blocks every ray entering it spares the children after it,
  /// so the cost of a likely blocker is far below its SAH cost.
  double cost = 0.0;
};

/// The summary of a leaf of `count` primitives starting at `refs`, in `box`.
OccluderSummary leaf_summary(const PrimRef* refs, uint32_t count, const Box3f& box,
                             const SahBuildOptions& options);

/// How much a child is worth visiting first, higher first. For likely_blocker: the chance that a
/// ray which enters the child's box is blocked there divided by the expected cost of looking
/// (both the summary's). Searching independent places in decreasing order of probability over
/// cost minimises the expected cost of finding the first success (Simon and Kadane, "Optimal
/// problem-solving search", Artificial Intelligence 6, 1975).
double occluder_score(const Box3f& box, const OccluderSummary& summary, OccluderOrder order);
// [ch04-occluder-score]

/// Orders a node's children by decreasing score (a stable sort: equal scores keep their spatial
/// order) and returns the node's summary. `kids` holds the children's summaries, in the node's
/// order, and is permuted with them.
template <int N>
OccluderSummary order_children(typename BuildTree<N>::Node& node,
                               std::array<OccluderSummary, N>& kids, const Box3f& node_box,
                               const SahBuildOptions& options);

/// Orders every node of a subtree stored with children after parents (`nodes[0]` the root,
/// whose box is `root_box`); leaves index `refs`. Returns the subtree's summary.
template <int N>
OccluderSummary order_subtree(std::vector<typename BuildTree<N>::Node>& nodes,
                              const Box3f& root_box, const PrimRef* refs,
                              const SahBuildOptions& options);

}  // namespace rtk::sah
