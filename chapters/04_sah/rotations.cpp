#include "04_sah/rotations.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>

#include "04_sah/binning.h"

namespace rtk::sah {

namespace {

/// Shrinking an area by less than this fraction is not worth a rotation.
constexpr double kMinRelativeGain = 1e-6;

/// A box as two float lanes, for estimating the area of a merge in a few vector operations.
struct FastBox {
  Lanes4 lower{0, 0, 0, 0}, upper{0, 0, 0, 0};
  FastBox() = default;
  explicit FastBox(const Box3f& b)
      : lower{b.lower.x, b.lower.y, b.lower.z, 0.0f}, upper{b.upper.x, b.upper.y, b.upper.z, 0.0f} {}
};
/// Half the area of the union of two boxes, in float.
RTK_INLINE float merged_area(const FastBox& a, const FastBox& b) {
  const Lanes4 d = max4(a.upper, b.upper) - min4(a.lower, b.lower);
  return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
}

// [ch04-rotate-estimate]
/// Nearly every swap a node offers would grow its boxes. A float estimate of the gain, off
/// from the exact one by about a millionth of the areas concerned where a swap can gain at
/// all, rules those out quickly; the candidates it leaves are priced exactly in double, so
/// the rotations made are the same. Swaps whose estimate falls this far (relative to the old
/// area) below the best gain so far are ruled out...
constexpr float kQuickMargin = 1e-5f;
/// ...where the old area is far from float's overflow and underflow (elsewhere every swap is
/// priced exactly).
inline bool quick_estimate(double old_area) { return old_area > 1e-30 && old_area < 1e30; }
// [ch04-rotate-estimate]

/// The best rotation found at one node.
struct Rotation {
  double gain = 0.0;
  int child = -1;                  ///< child-grandchild: the child; grandchild-grandchild: -1
  int parent_a = -1, slot_a = -1;  ///< the (first) grandchild: child index of its parent, slot
  int parent_b = -1, slot_b = -1;  ///< the second grandchild (grandchild-grandchild only)
  Box3f box_a, box_b;              ///< the new boxes of parent_a and parent_b
};

/// The height of a child: 0 for a leaf, the height of its node otherwise.
template <int N>
int height_of(const typename BuildTree<N>::Child& c, const std::vector<int>& height) {
  return c.is_leaf() ? 0 : height[c.index];
}

// [ch04-rotate]
template <int N>
bool rotate_at(std::vector<typename BuildTree<N>::Node>& nodes, std::vector<int>& height,
               uint32_t x, std::vector<uint64_t>& changed, uint64_t& clock, bool price_every_swap) {
  auto& node = nodes[x];
  const int k = node.num_children;
  // For every inner child p and each of its slots l: the box of p's children without l, and
  // p's height without l.
  std::array<std::array<Box3f, N>, N> without;
  std::array<std::array<int, N>, N> height_without;
  // The same boxes, and the grandchildren's, as float lanes for the quick estimate below.
  std::array<std::array<FastBox, N>, N> fast_without, fast_grandchild;
  std::array<FastBox, N> fast_child;
  for (int p = 0; p < k; ++p) {
    if (node.children[p].is_leaf()) continue;
    const auto& inner = nodes[node.children[p].index];
    const int m = inner.num_children;
    std::array<Box3f, N + 1> suffix;
    std::array<int, N + 1> suffix_height{};
    for (int l = m - 1; l >= 0; --l) {
      suffix[l] = merge(suffix[l + 1], inner.children[l].box);
      suffix_height[l] = std::max(suffix_height[l + 1], height_of<N>(inner.children[l], height));
    }
    Box3f prefix;
    int prefix_height = 0;
    for (int l = 0; l < m; ++l) {
      without[p][l] = merge(prefix, suffix[l + 1]);
      height_without[p][l] = std::max(prefix_height, suffix_height[l + 1]);
      prefix.extend(inner.children[l].box);
      prefix_height = std::max(prefix_height, height_of<N>(inner.children[l], height));
      fast_without[p][l] = FastBox(without[p][l]);
      if constexpr (N <= kGrandchildSwapWidth)
        fast_grandchild[p][l] = FastBox(inner.children[l].box);
    }
  }
  std::array<double, N> area;
  for (int i = 0; i < k; ++i) area[i] = half_area(node.children[i].box), fast_child[i] = FastBox(node.children[i].box);
  // The node's height if children a and b (b may be -1) get heights ha and hb: a rotation may
  // not make the subtree taller, or a chain of rotations could make the tree deeper than the
  // traversal stacks allow.
  auto node_height = [&](int a, int ha, int b, int hb) {
    int h = std::max(ha, hb);
    for (int i = 0; i < k; ++i)
      if (i != a && i != b) h = std::max(h, height_of<N>(node.children[i], height));
    return h + 1;
  };
  Rotation best;
  // Child c swaps with grandchild (p, l): p's box becomes without[p][l] + box(c).
  for (int p = 0; p < k; ++p) {
    if (node.children[p].is_leaf()) continue;
    const auto& inner = nodes[node.children[p].index];
    const double old_area = area[p];
    const bool quick = !price_every_swap && quick_estimate(old_area);
    const float fast_old = float(old_area);
    for (int c = 0; c < k; ++c) {
      if (c == p) continue;
      for (int l = 0; l < inner.num_children; ++l) {
        if (quick && fast_old - merged_area(fast_without[p][l], fast_child[c]) <
                         float(best.gain) - kQuickMargin * fast_old)
          continue;
        const Box3f box = merge(without[p][l], node.children[c].box);
        const double gain = old_area - half_area(box);
        if (!(gain > best.gain && gain > kMinRelativeGain * old_area)) continue;
        const int new_p =
            1 + std::max(height_without[p][l], height_of<N>(node.children[c], height));
        if (node_height(c, height_of<N>(inner.children[l], height), p, new_p) > height[x]) continue;
        best = {gain, c, p, l, -1, -1, box, Box3f()};
      }
    }
  }
  // Grandchild (p, l) swaps with grandchild (q, r), in nodes narrow enough for them to pay
  // (kGrandchildSwapWidth).
  if constexpr (N <= kGrandchildSwapWidth) {
    for (int p = 0; p < k; ++p) {
      if (node.children[p].is_leaf()) continue;
      const auto& a = nodes[node.children[p].index];
      for (int q = p + 1; q < k; ++q) {
        if (node.children[q].is_leaf()) continue;
        const auto& b = nodes[node.children[q].index];
        const double old_area = area[p] + area[q];
        const bool quick = !price_every_swap && quick_estimate(old_area);
        const float fast_old = float(old_area);
        for (int l = 0; l < a.num_children; ++l) {
          for (int r = 0; r < b.num_children; ++r) {
            if (quick && fast_old - merged_area(fast_without[p][l], fast_grandchild[q][r]) -
                                 merged_area(fast_without[q][r], fast_grandchild[p][l]) <
                             float(best.gain) - kQuickMargin * fast_old)
              continue;
            const Box3f box_a = merge(without[p][l], b.children[r].box);
            const Box3f box_b = merge(without[q][r], a.children[l].box);
            const double gain = old_area - half_area(box_a) - half_area(box_b);
            if (!(gain > best.gain && gain > kMinRelativeGain * old_area)) continue;
            const int new_p =
                1 + std::max(height_without[p][l], height_of<N>(b.children[r], height));
            const int new_q =
                1 + std::max(height_without[q][r], height_of<N>(a.children[l], height));
            if (node_height(p, new_p, q, new_q) > height[x]) continue;
            best = {gain, -1, p, l, q, r, box_a, box_b};
          }
        }
      }
    }
  }
  if (best.parent_a < 0) return false;
  // Apply it: swap the two entries and give the parents in between their new boxes.
  auto& parent_a = nodes[node.children[best.parent_a].index];
  if (best.child >= 0) {
    std::swap(node.children[best.child], parent_a.children[best.slot_a]);
  } else if constexpr (N <= kGrandchildSwapWidth) {
    auto& parent_b = nodes[node.children[best.parent_b].index];
    std::swap(parent_a.children[best.slot_a], parent_b.children[best.slot_b]);
    node.children[best.parent_b].box = best.box_b;
  }
  node.children[best.parent_a].box = best.box_a;
  // The heights of the nodes in between, and of this one, follow from their children.
  auto refresh = [&](uint32_t index) {
    int h = 0;
    for (int i = 0; i < nodes[index].num_children; ++i)
      h = std::max(h, height_of<N>(nodes[index].children[i], height));
    height[index] = h + 1;
  };
  refresh(node.children[best.parent_a].index);
  if (best.parent_b >= 0) refresh(node.children[best.parent_b].index);
  refresh(x);
  ++clock;
  changed[node.children[best.parent_a].index] = clock;
  if (best.parent_b >= 0) changed[node.children[best.parent_b].index] = clock;
  changed[x] = clock;
  return true;
}
// [ch04-rotate]

/// Every node's height (1 for a node of leaves), computed depth first from the root nodes[0].
template <int N>
std::vector<int> heights(const std::vector<typename BuildTree<N>::Node>& nodes) {
  std::vector<int> height(nodes.size(), 0);
  // Post-order with an explicit stack: a node is finished when all its children are.
  std::vector<std::pair<uint32_t, bool>> stack{{0u, false}};
  while (!stack.empty()) {
    auto [index, expanded] = stack.back();
    stack.pop_back();
    const auto& node = nodes[index];
    if (!expanded) {
      stack.push_back({index, true});
      for (int i = 0; i < node.num_children; ++i)
        if (!node.children[i].is_leaf()) stack.push_back({node.children[i].index, false});
      continue;
    }
    int h = 0;
    for (int i = 0; i < node.num_children; ++i)
      h = std::max(h, height_of<N>(node.children[i], height));
    height[index] = h + 1;
  }
  return height;
}

}  // namespace

template <int N>
size_t rotate_tree(std::vector<typename BuildTree<N>::Node>& nodes, int rounds,
                   bool price_every_swap) {
  size_t applied = 0;
  if (nodes.empty()) return 0;
  std::vector<int> height = heights<N>(nodes);
  // What a node's search reads is its children, its inner children's children and heights,
  // and its inner grandchildren's heights. `changed` stamps each node with the time its
  // children or height last changed, `searched` each node with the time of its last search,
  // which found nothing: a node none of whose stamps is newer would find nothing again, and
  // is skipped. The rotations made are the same as searching every node every round.
  uint64_t clock = 1;
  std::vector<uint64_t> changed(nodes.size(), 0), searched(nodes.size(), 0);
  auto unchanged_since = [&](uint32_t x, uint64_t time) {
    const auto& node = nodes[x];
    if (changed[x] > time) return false;
    for (int i = 0; i < node.num_children; ++i) {
      const auto& c = node.children[i];
      if (c.is_leaf()) continue;
      if (changed[c.index] > time) return false;
      const auto& inner = nodes[c.index];
      for (int l = 0; l < inner.num_children; ++l)
        if (!inner.children[l].is_leaf() && changed[inner.children[l].index] > time) return false;
    }
    return true;
  };
  for (int round = 0; round < rounds; ++round) {
    size_t in_round = 0;
    // Highest index first: before any rotation, children come after their parents, so this is
    // bottom-up, and each subtree is improved before its parent looks at it.
    for (size_t x = nodes.size(); x-- > 0;) {
      if (searched[x] && unchanged_since(uint32_t(x), searched[x])) continue;
      const uint64_t now = clock;
      if (rotate_at<N>(nodes, height, uint32_t(x), changed, clock, price_every_swap))
        ++in_round;
      else
        searched[x] = now;
    }
    applied += in_round;
    if (in_round == 0) break;
  }
  return applied;
}

template <int N>
std::vector<typename BuildTree<N>::Node> preorder(
    const std::vector<typename BuildTree<N>::Node>& nodes) {
  std::vector<typename BuildTree<N>::Node> out;
  out.reserve(nodes.size());
  if (nodes.empty()) return out;
  // Each stack entry is an old node index and the slot in `out` that points to it (-1: root).
  std::vector<std::pair<uint32_t, int64_t>> stack{{0u, -1}};
  while (!stack.empty()) {
    const auto [old_index, referrer] = stack.back();
    stack.pop_back();
    const uint32_t new_index = uint32_t(out.size());
    if (referrer >= 0) out[size_t(referrer / N)].children[size_t(referrer % N)].index = new_index;
    out.push_back(nodes[old_index]);
    const auto& node = out.back();
    for (int c = node.num_children - 1; c >= 0; --c)
      if (!node.children[c].is_leaf())
        stack.push_back({node.children[c].index, int64_t(new_index) * N + c});
  }
  return out;
}

template size_t rotate_tree<2>(std::vector<BuildTree<2>::Node>&, int, bool);
template size_t rotate_tree<4>(std::vector<BuildTree<4>::Node>&, int, bool);
template size_t rotate_tree<8>(std::vector<BuildTree<8>::Node>&, int, bool);
template size_t rotate_tree<16>(std::vector<BuildTree<16>::Node>&, int, bool);
template std::vector<BuildTree<2>::Node> preorder<2>(const std::vector<BuildTree<2>::Node>&);
template std::vector<BuildTree<4>::Node> preorder<4>(const std::vector<BuildTree<4>::Node>&);
template std::vector<BuildTree<8>::Node> preorder<8>(const std::vector<BuildTree<8>::Node>&);
template std::vector<BuildTree<16>::Node> preorder<16>(const std::vector<BuildTree<16>::Node>&);

}  // namespace rtk::sah
