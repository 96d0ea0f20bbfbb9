/// \file
/// Test-only checks of a BuildTree, written independently of the builder: structural
/// invariants, an independent SAH recomputation, and whether a ray can reach a given primitive.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "01_base/ray.h"
#include "02_bvh2/build_tree.h"

namespace rtk::test {

/// Why `tree` is not a valid tree over the valid references of `refs` with leaves of at most
/// `max_leaf` primitives, or an empty string. Checked: every valid reference's primitive is in
/// exactly one leaf and no invalid one is; every box contains its primitives' boxes and lies in
/// its parent's; with `tight`, every box is exactly the union of what it holds; 2 to N children
/// per node; children after their parents; every node reached exactly once.
template <int N>
std::string check_tree(const BuildTree<N>& tree, std::span<const PrimRef> refs, int max_leaf,
                       bool tight = true) {
  std::ostringstream err;
  auto valid = [](const PrimRef& r) {
    return std::isfinite(r.lower.x) && std::isfinite(r.lower.y) && std::isfinite(r.lower.z) &&
           std::isfinite(r.upper.x) && std::isfinite(r.upper.y) && std::isfinite(r.upper.z) &&
           r.lower.x <= r.upper.x && r.lower.y <= r.upper.y && r.lower.z <= r.upper.z;
  };
  // Boxes by primitive ID (IDs may repeat in the input only if the caller made them so).
  std::vector<int> expected(refs.size(), 0);
  std::vector<Box3f> box_of(refs.size());
  size_t valid_count = 0;
  for (const PrimRef& r : refs) {
    if (r.prim >= refs.size()) return "test input: primitive IDs must be below the reference count";
    if (valid(r)) ++expected[r.prim], box_of[r.prim] = r.box(), ++valid_count;
  }
  if (tree.prim_ids.size() != valid_count) {
    err << "prim_ids holds " << tree.prim_ids.size() << " entries for " << valid_count
        << " valid references";
    return err.str();
  }
  if (valid_count == 0) return tree.empty() ? "" : "a tree over nothing must be empty";

  std::vector<int> seen_prim(refs.size(), 0);
  std::vector<int> covered(tree.prim_ids.size(), 0);
  std::vector<int> seen_node(tree.nodes.size(), 0);
  auto eq = [](const Box3f& a, const Box3f& b) { return std::memcmp(&a, &b, sizeof a) == 0; };

  // Returns the union of what `c` holds, checking it on the way.
  struct Walker {
    const BuildTree<N>& tree;
    std::vector<int>& seen_prim;
    std::vector<int>& covered;
    std::vector<int>& seen_node;
    const std::vector<Box3f>& box_of;
    std::ostringstream& err;
    int max_leaf;
    bool tight;
    decltype(eq)& same;

    Box3f walk(const typename BuildTree<N>::Child& c, uint32_t parent_index, bool is_root) {
      Box3f u;
      if (c.is_leaf()) {
        if (c.leaf_count > uint32_t(max_leaf))
          err << "leaf of " << c.leaf_count << " > " << max_leaf << "; ";
        if (size_t(c.index) + c.leaf_count > tree.prim_ids.size()) {
          err << "leaf range out of prim_ids; ";
          return u;
        }
        for (uint32_t i = c.index; i < c.index + c.leaf_count; ++i) {
          ++covered[i];
          const uint32_t id = tree.prim_ids[i];
          if (id >= seen_prim.size()) {
            err << "bad prim id " << id << "; ";
            continue;
          }
          ++seen_prim[id];
          if (!c.box.contains(box_of[id])) err << "leaf box misses prim " << id << "; ";
          u.extend(box_of[id]);
        }
      } else {
        if (c.index >= tree.nodes.size()) {
          err << "node index out of range; ";
          return u;
        }
        if (!is_root && c.index <= parent_index)
          err << "child " << c.index << " not after parent " << parent_index << "; ";
        if (seen_node[c.index]++) {
          err << "node " << c.index << " reached twice; ";
          return u;
        }
        const auto& node = tree.nodes[c.index];
        if (node.num_children < 2 || node.num_children > N)
          err << "node with " << node.num_children << " children; ";
        for (int i = 0; i < node.num_children && i < N; ++i) {
          const auto& child = node.children[i];
          if (!c.box.contains(child.box))
            err << "child box outside parent at node " << c.index << "; ";
          u.extend(walk(child, c.index, false));
        }
      }
      if (tight && !same(u, c.box)) err << (c.is_leaf() ? "leaf" : "node") << " box not tight; ";
      return u;
    }
  } walker{tree, seen_prim, covered, seen_node, box_of, err, max_leaf, tight, eq};

  walker.walk(tree.root, 0, true);
  for (size_t i = 0; i < refs.size(); ++i)
    if (seen_prim[i] != expected[i]) {
      err << "prim " << i << " in " << seen_prim[i] << " leaves; ";
      break;
    }
  for (size_t i = 0; i < covered.size(); ++i)
    if (covered[i] != 1) {
      err << "prim_ids entry " << i << " in " << covered[i] << " leaves; ";
      break;
    }
  for (size_t i = 0; i < seen_node.size(); ++i)
    if (seen_node[i] != 1) {
      err << "node " << i << " reached " << seen_node[i] << " times; ";
      break;
    }
  return err.str();
}

/// The SAH cost recomputed recursively, as the expected cost of a ray that enters the root
/// box: cost(node) = Ct + sum over children of area(child) / area(node) * cost(child), and
/// Ci * count for a leaf, or Ci * ceil(count / leaf_block) when its primitives are tested in
/// blocks. (sah_cost() sums over boxes instead; the two must agree.)
template <int N>
double recursive_sah(const BuildTree<N>& tree, double ct, double ci, int leaf_block = 1) {
  if (tree.empty()) return 0.0;
  struct R {
    const BuildTree<N>& t;
    double ct, ci;
    int block;
    double cost(const typename BuildTree<N>::Child& c) const {
      if (c.is_leaf()) return ci * std::ceil(double(c.leaf_count) / block);
      const auto& node = t.nodes[c.index];
      const double area = c.box.half_area();
      double sum = ct;
      for (int i = 0; i < node.num_children; ++i)
        sum += (area > 0 ? node.children[i].box.half_area() / area : 1.0) * cost(node.children[i]);
      return sum;
    }
  } r{tree, ct, ci, leaf_block};
  return r.cost(tree.root);
}

/// Whether the segment [tnear, tfar] of `ray` meets the box, in double precision, with the box
/// padded by a relative `pad` so that a conservative answer is given at the borders.
inline bool segment_hits_box(const Ray& ray, const Box3f& box, double pad = 1e-5) {
  double t0 = ray.tnear, t1 = ray.tfar;
  for (int a = 0; a < 3; ++a) {
    const double size = double(box.upper[a]) - box.lower[a];
    const double margin =
        pad * (size + std::fabs(double(box.lower[a])) + std::fabs(double(box.upper[a]))) + 1e-30;
    const double lo = box.lower[a] - margin, hi = box.upper[a] + margin;
    const double o = ray.org[a], d = ray.dir[a];
    if (d == 0.0) {
      if (o < lo || o > hi) return false;
      continue;
    }
    double near = (lo - o) / d, far = (hi - o) / d;
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
    if (t0 > t1 * (1 + 1e-9) + 1e-30) return false;
  }
  return true;
}

/// Whether a ray that traverses the tree, entering every box its segment meets, reaches a leaf
/// holding primitive `prim`: the tree never hides the primitive a ray hits.
template <int N>
bool reaches(const BuildTree<N>& tree, const Ray& ray, uint32_t prim) {
  if (tree.empty()) return false;
  std::vector<typename BuildTree<N>::Child> stack{tree.root};
  while (!stack.empty()) {
    const auto c = stack.back();
    stack.pop_back();
    if (!segment_hits_box(ray, c.box)) continue;
    if (c.is_leaf()) {
      for (uint32_t i = c.index; i < c.index + c.leaf_count; ++i)
        if (tree.prim_ids[i] == prim) return true;
      continue;
    }
    const auto& node = tree.nodes[c.index];
    for (int i = 0; i < node.num_children; ++i) stack.push_back(node.children[i]);
  }
  return false;
}

/// Whether two trees are the same bit for bit: root, nodes (in order) and prim_ids.
template <int N>
bool identical(const BuildTree<N>& a, const BuildTree<N>& b) {
  auto same_child = [](const typename BuildTree<N>::Child& x,
                       const typename BuildTree<N>::Child& y) {
    return std::memcmp(&x.box, &y.box, sizeof x.box) == 0 && x.index == y.index &&
           x.leaf_count == y.leaf_count;
  };
  if (!same_child(a.root, b.root) || a.nodes.size() != b.nodes.size() || a.prim_ids != b.prim_ids)
    return false;
  for (size_t i = 0; i < a.nodes.size(); ++i) {
    if (a.nodes[i].num_children != b.nodes[i].num_children) return false;
    for (int c = 0; c < a.nodes[i].num_children; ++c)
      if (!same_child(a.nodes[i].children[c], b.nodes[i].children[c])) return false;
  }
  return true;
}

}  // namespace rtk::test
