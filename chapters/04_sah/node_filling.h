/// \file
/// The skeleton that every SAH builder of the book shares (this chapter's object splits and
/// chapter 5's spatial splits): how a node of N children is filled from a set that wants to be
/// split, and how one thread builds a whole subtree depth first. It is generic over the
/// builder's set of primitives and its split, so that each builder keeps only what is its own:
/// how a set is priced, and how it is cut in two.
#pragma once

#include <array>
#include <concepts>
#include <cstdint>
#include <utility>
#include <vector>

#include "02_bvh2/build_tree.h"
#include "04_sah/sah_options.h"

namespace rtk::sah {

/// A set of primitives as node filling sees it: its size, its box, whether the SAH's leaf test
/// wants it split (`wants_split`), whether any split exists (`splittable`), and how much the SAH
/// falls when it is split inside its parent's node (`gain`).
template <class S>
concept FillableSet = std::movable<S> && requires(const S& s) {
  { s.size() } -> std::convertible_to<uint32_t>;
  { s.bounds } -> std::convertible_to<Box3f>;
  { s.wants_split } -> std::convertible_to<bool>;
  { s.gain } -> std::convertible_to<double>;
  { s.splittable() } -> std::convertible_to<bool>;
};

// [ch04-fill-node]
/// Fills one node: split the set, then keep splitting the child whose split gains most until
/// the node has N children or no split gains anything. A free slot costs no traversal step, so
/// inside the node a split is worth making whenever it lowers the intersection term, even where
/// the binary leaf test would have kept a leaf. Children stay in the order of their ranges,
/// which is the spatial order along the split axes. `split(set, median)` cuts a set in two.
///
/// Past kMedianFillDepth levels the SAH has produced a degenerate chain (centroids spaced
/// exponentially can make every split peel off a few primitives), and the node is filled with
/// `median` splits of the largest child instead: the levels left are then at most log_N of the
/// primitive count, and traversal stacks stay within their bounds. Returns the child count.
template <int N, FillableSet Set, class SplitFn>
int fill_node(Set set, std::array<Set, N>& kids, int depth, int max_leaf_size, SplitFn&& split) {
  const bool median = depth >= kMedianFillDepth<N>;
  kids[0] = std::move(set);
  int k = 1;
  while (k < N) {
    int best = -1;
    for (int i = 0; i < k; ++i) {
      // (The set itself wants a split, so the first one is always made.)
      const bool candidate = median ? kids[i].size() > uint32_t(max_leaf_size) || k == 1
                                    : kids[i].wants_split || (kids[i].splittable() && kids[i].gain > 0.0);
      const bool better =
          best < 0 || (median ? kids[i].size() > kids[best].size() : kids[i].gain > kids[best].gain);
      if (candidate && better) best = i;
    }
    if (best < 0) break;
    auto [left, right] = split(std::move(kids[best]), median);
    for (int i = k; i > best + 1; --i) kids[i] = std::move(kids[i - 1]);
    kids[best] = std::move(left);
    kids[best + 1] = std::move(right);
    ++k;
  }
  if (median)
    for (int i = 0; i < k; ++i) kids[i].wants_split = kids[i].size() > uint32_t(max_leaf_size);
  return k;
}
// [ch04-fill-node]

// [ch04-depth-first]
/// Builds the subtree of `root` (a set that wants a split, its node at `depth`) on one thread,
/// depth first with an explicit stack, since a badly balanced subtree can be deep. Its nodes
/// are appended to `nodes` in preorder, the subtree's root first. `fill(set, kids, depth)`
/// fills a node; `leaf(set)` makes the leaf child of a set that stays a leaf.
template <int N, FillableSet Set, class Fill, class Leaf>
void build_depth_first(std::vector<typename BuildTree<N>::Node>& nodes, Set root, int depth, Fill&& fill,
                       Leaf&& leaf) {
  struct Work {
    Set set;
    int64_t referrer;  // parent index * N + slot, or -1 for the subtree's root
    int depth;
  };
  std::vector<Work> stack;
  stack.push_back({std::move(root), -1, depth});
  std::array<Set, N> kids;
  while (!stack.empty()) {
    Work work = std::move(stack.back());
    stack.pop_back();
    const uint32_t index = uint32_t(nodes.size());
    if (work.referrer >= 0) nodes[size_t(work.referrer / N)].children[size_t(work.referrer % N)].index = index;
    const int k = fill(std::move(work.set), kids, work.depth);
    auto& node = nodes.emplace_back();
    node.num_children = k;
    for (int i = k - 1; i >= 0; --i) {  // pushed last to first, so built first to last
      if (kids[i].wants_split) {
        node.children[size_t(i)].box = kids[i].bounds;
        stack.push_back({std::move(kids[i]), int64_t(index) * N + i, work.depth + 1});
      } else {
        node.children[size_t(i)] = leaf(kids[i]);
      }
    }
  }
}
// [ch04-depth-first]

}  // namespace rtk::sah
