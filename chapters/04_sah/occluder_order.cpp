#include "04_sah/occluder_order.h"

#include <algorithm>
#include <numeric>

#include "04_sah/binning.h"

namespace rtk::sah {

OccluderSummary leaf_summary(const PrimRef* refs, uint32_t count, const Box3f& box,
                             const SahBuildOptions& options) {
  double surface = 0.0;
  for (uint32_t i = 0; i < count; ++i) surface += 0.5 * half_area(refs[i].box());
  const double area = half_area(box);
  OccluderSummary s;
  s.blocks = area > 0.0 ? std::min(1.0, surface / area) : 0.0;
  s.cost = double(options.intersection_cost) * leaf_tests(count, options.leaf_block);
  return s;
}

double occluder_score(const Box3f& box, const OccluderSummary& summary, OccluderOrder order) {
  if (order == OccluderOrder::largest_box) return half_area(box);
  if (order != OccluderOrder::likely_blocker || summary.cost <= 0.0) return 0.0;
  return summary.blocks / summary.cost;
}

template <int N>
OccluderSummary order_children(typename BuildTree<N>::Node& node,
                               std::array<OccluderSummary, N>& kids, const Box3f& node_box,
                               const SahBuildOptions& options) {
  const int k = node.num_children;
  if (options.occluder_order != OccluderOrder::off) {
    std::array<double, N> score;
    std::array<int, N> order;
    for (int i = 0; i < k; ++i)
      score[i] = occluder_score(node.children[i].box, kids[i], options.occluder_order);
    std::iota(order.begin(), order.begin() + k, 0);
    std::stable_sort(order.begin(), order.begin() + k,
                     [&](int a, int b) { return score[a] > score[b]; });
    const auto children = node.children;
    const auto summaries = kids;
    for (int i = 0; i < k; ++i)
      node.children[i] = children[order[i]], kids[i] = summaries[order[i]];
  }
  // [ch04-occluder-cost]
  // The node's summary: a shadow ray entering it tests all boxes, then enters each child with
  // the probability area(child) / area(node), in the order just chosen, unless a child before
  // it has blocked it.
  OccluderSummary s;
  s.cost = options.traversal_cost;
  const double area = half_area(node_box);
  double unblocked = 1.0;
  for (int i = 0; i < k; ++i) {
    const double enters = area > 0.0 ? half_area(node.children[i].box) / area : 1.0;
    s.cost += unblocked * enters * kids[i].cost;
    unblocked *= 1.0 - enters * kids[i].blocks;
  }
  s.blocks = 1.0 - unblocked;
  return s;
  // [ch04-occluder-cost]
}

template <int N>
OccluderSummary order_subtree(std::vector<typename BuildTree<N>::Node>& nodes,
                              const Box3f& root_box, const PrimRef* refs,
                              const SahBuildOptions& options) {
  std::vector<OccluderSummary> summary(nodes.size());
  // Children have higher indices than their parents: a backward sweep sees children first.
  for (size_t x = nodes.size(); x-- > 0;) {
    auto& node = nodes[x];
    std::array<OccluderSummary, N> kids;
    for (int i = 0; i < node.num_children; ++i) {
      const auto& child = node.children[i];
      kids[i] = child.is_leaf()
                    ? leaf_summary(refs + child.index, child.leaf_count, child.box, options)
                    : summary[child.index];
    }
    // The node's own box is in its parent; only the root's is passed in.
    Box3f box;
    if (x == 0) {
      box = root_box;
    } else {
      for (int i = 0; i < node.num_children; ++i) box.extend(node.children[i].box);
    }
    summary[x] = order_children<N>(node, kids, box, options);
  }
  return nodes.empty() ? OccluderSummary{} : summary[0];
}

template OccluderSummary order_children<2>(BuildTree<2>::Node&, std::array<OccluderSummary, 2>&,
                                           const Box3f&, const SahBuildOptions&);
template OccluderSummary order_children<4>(BuildTree<4>::Node&, std::array<OccluderSummary, 4>&,
                                           const Box3f&, const SahBuildOptions&);
template OccluderSummary order_children<8>(BuildTree<8>::Node&, std::array<OccluderSummary, 8>&,
                                           const Box3f&, const SahBuildOptions&);
template OccluderSummary order_children<16>(BuildTree<16>::Node&, std::array<OccluderSummary, 16>&,
                                            const Box3f&, const SahBuildOptions&);
template OccluderSummary order_subtree<2>(std::vector<BuildTree<2>::Node>&, const Box3f&,
                                          const PrimRef*, const SahBuildOptions&);
template OccluderSummary order_subtree<4>(std::vector<BuildTree<4>::Node>&, const Box3f&,
                                          const PrimRef*, const SahBuildOptions&);
template OccluderSummary order_subtree<8>(std::vector<BuildTree<8>::Node>&, const Box3f&,
                                          const PrimRef*, const SahBuildOptions&);
template OccluderSummary order_subtree<16>(std::vector<BuildTree<16>::Node>&, const Box3f&,
                                           const PrimRef*, const SahBuildOptions&);

}  // namespace rtk::sah
