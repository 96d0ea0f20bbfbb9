// Chapter 4: what the heuristics buy. N-ary filling fills nodes, rotations never make the SAH
// worse, occluder ordering only reorders, and rays can still reach what they hit.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "01_base/ray_sets.h"
#include "04_sah/build_sah.h"
#include "04_sah/occluder_order.h"
#include "04_sah/rotations.h"
#include "04_sah/tree_checks.h"
#include "testing/brute_force.h"
#include "testing/scenes.h"

namespace {

using namespace rtk;

struct NamedScene {
  std::string name;
  TriangleMesh mesh;
};

std::vector<NamedScene> scenes() {
  std::vector<NamedScene> s;
  s.push_back({"sphere", test::make_sphere(30, 60)});
  s.push_back({"soup", test::make_random_soup(4000, 41)});
  s.push_back({"terrain", test::make_terrain(40, 42)});
  s.push_back({"slivers", test::make_slivers(2000, 43)});
  return s;
}

/// Every child of the tree as (box corners, leaf count), sorted: the tree's content without its
/// order.
template <int N>
std::vector<std::tuple<float, float, float, float, float, float, uint32_t>> children_multiset(
    const BuildTree<N>& t) {
  std::vector<std::tuple<float, float, float, float, float, float, uint32_t>> all;
  for (const auto& node : t.nodes)
    for (int i = 0; i < node.num_children; ++i) {
      const auto& c = node.children[i];
      all.emplace_back(c.box.lower.x, c.box.lower.y, c.box.lower.z, c.box.upper.x, c.box.upper.y,
                       c.box.upper.z, c.leaf_count);
    }
  std::sort(all.begin(), all.end());
  return all;
}

}  // namespace

TEST_CASE_TEMPLATE("ch04: a node has fewer than N children only when no child wanted a split", W,
                   std::integral_constant<int, 4>, std::integral_constant<int, 8>) {
  constexpr int N = W::value;
  for (const auto& scene : scenes()) {
    CAPTURE(scene.name);
    const std::vector<PrimRef> refs = make_prim_refs(scene.mesh);
    SahBuildOptions options;
    options.rotations = false;  // rotations may move an inner child under a partly filled node
    const BuildTree<N> tree = build_binned_sah<N>(refs, options);
    size_t full = 0;
    bool only_leaves = true;
    for (const auto& node : tree.nodes) {
      if (node.num_children == N) {
        ++full;
        continue;
      }
      for (int i = 0; i < node.num_children; ++i) only_leaves &= node.children[i].is_leaf();
    }
    CHECK(only_leaves);
    CHECK(full > 0);
  }
}

TEST_CASE_TEMPLATE("ch04: rotations never increase the SAH", W, std::integral_constant<int, 2>,
                   std::integral_constant<int, 4>, std::integral_constant<int, 8>) {
  constexpr int N = W::value;
  size_t total_rotations = 0;
  for (const auto& scene : scenes()) {
    CAPTURE(scene.name);
    const std::vector<PrimRef> refs = make_prim_refs(scene.mesh);
    SahBuildOptions options;
    options.rotations = false;
    const double without = sah_cost(build_binned_sah<N>(refs, options));
    options.rotations = true;
    SahBuildStats stats;
    const BuildTree<N> rotated = build_binned_sah<N>(refs, options, &stats);
    const double with = sah_cost(rotated);
    CHECK(with <= without * (1.0 + 1e-12));
    if (stats.rotations > 0) CHECK(with < without);
    total_rotations += stats.rotations;
    CHECK(test::check_tree(rotated, refs, options.max_leaf_size) == "");
  }
  CHECK(total_rotations > 0);  // the test exercised rotations
}

// [ch04-test-rotation-search]
TEST_CASE_TEMPLATE(
    "ch04: the fast rotation search makes the rotations that pricing every swap "
    "exactly makes",
    W, std::integral_constant<int, 2>, std::integral_constant<int, 4>,
    std::integral_constant<int, 8>, std::integral_constant<int, 16>) {
  constexpr int N = W::value;
  size_t total_rotations = 0;
  for (const auto& scene : scenes()) {
    for (const int leaf_block : {1, 8}) {
      CAPTURE(scene.name);
      CAPTURE(leaf_block);
      SahBuildOptions options =
          leaf_block == 1 ? SahBuildOptions{} : block_priced_options(leaf_block);
      options.rotations = false;
      const BuildTree<N> tree = build_binned_sah<N>(make_prim_refs(scene.mesh), options);
      REQUIRE(tree.root.index == 0);
      std::vector<typename BuildTree<N>::Node> fast(tree.nodes.begin(), tree.nodes.end()), exact = fast;
      const size_t applied = sah::rotate_tree<N>(fast, 3);
      CHECK(sah::rotate_tree<N>(exact, 3, /*price_every_swap=*/true) == applied);
      total_rotations += applied;
      // The same swaps: every node holds the same children with the same boxes, bit for bit.
      bool same = true;
      for (size_t i = 0; i < fast.size(); ++i) {
        same &= fast[i].num_children == exact[i].num_children;
        for (int c = 0; c < fast[i].num_children; ++c) {
          const auto &a = fast[i].children[c], &b = exact[i].children[c];
          same &= a.index == b.index && a.leaf_count == b.leaf_count &&
                  std::memcmp(&a.box, &b.box, sizeof a.box) == 0;
        }
      }
      CHECK(same);
    }
  }
  CHECK(total_rotations > 0);  // the test exercised rotations
}
// [ch04-test-rotation-search]

// [ch04-test-grandchild-swaps]
TEST_CASE_TEMPLATE("ch04: nodes of up to four children swap two grandchildren, wider ones do not",
                   W, std::integral_constant<int, 2>, std::integral_constant<int, 4>,
                   std::integral_constant<int, 8>, std::integral_constant<int, 16>) {
  constexpr int N = W::value;
  // The root has two inner children, each with a leaf near x = 0 and a leaf near x = 10: p's
  // at y = 0, q's at y = 2. Swapping p's far leaf with q's near one shrinks both boxes from
  // eleven units long to one; no swap of a child with a grandchild shrinks anything.
  using Tree = BuildTree<N>;
  auto leaf = [](float x, float y, uint32_t first) {
    typename Tree::Child c;
    c.box = Box3f(Vec3f(x, y, 0.0f), Vec3f(x + 1.0f, y + 1.0f, 1.0f));
    c.index = first;
    c.leaf_count = 1;
    return c;
  };
  std::vector<typename Tree::Node> nodes(3);
  nodes[1].children[0] = leaf(0.0f, 0.0f, 0), nodes[1].children[1] = leaf(10.0f, 0.0f, 1);
  nodes[2].children[0] = leaf(0.0f, 2.0f, 2), nodes[2].children[1] = leaf(10.0f, 2.0f, 3);
  nodes[1].num_children = nodes[2].num_children = nodes[0].num_children = 2;
  for (uint32_t p : {1u, 2u}) {
    auto& child = nodes[0].children[p - 1];
    child.index = p;
    child.box = merge(nodes[p].children[0].box, nodes[p].children[1].box);
  }
  const size_t applied = sah::rotate_tree<N>(nodes, 3);
  CHECK(applied == (N <= 4 ? 1u : 0u));
  // After the swap each child holds the two leaves at one x: a box one unit wide.
  for (int c = 0; c < 2; ++c) {
    const Box3f& box = nodes[0].children[c].box;
    CHECK(box.upper.x - box.lower.x == (N <= 4 ? 1.0f : 11.0f));
  }
}
// [ch04-test-grandchild-swaps]

TEST_CASE("ch04: occluder ordering permutes children and nothing else") {
  for (const auto& scene : scenes()) {
    CAPTURE(scene.name);
    const std::vector<PrimRef> refs = make_prim_refs(scene.mesh);
    SahBuildOptions options;
    options.occluder_order = OccluderOrder::off;
    const BuildTree<4> plain = build_binned_sah<4>(refs, options);
    for (const OccluderOrder order : {OccluderOrder::largest_box, OccluderOrder::likely_blocker}) {
      options.occluder_order = order;
      const BuildTree<4> ordered = build_binned_sah<4>(refs, options);
      CHECK(test::check_tree(ordered, refs, options.max_leaf_size) == "");
      CHECK(children_multiset(ordered) == children_multiset(plain));
      CHECK(sah_cost(ordered) == doctest::Approx(sah_cost(plain)).epsilon(1e-12));
      CHECK(ordered.prim_ids == plain.prim_ids);
    }
    // largest_box: every node's children by non-increasing area (checked independently here).
    options.occluder_order = OccluderOrder::largest_box;
    const BuildTree<4> by_area = build_binned_sah<4>(refs, options);
    bool sorted = true;
    size_t reordered = 0;
    for (const auto& node : by_area.nodes)
      for (int i = 1; i < node.num_children; ++i) {
        sorted &= !(node.children[i].box.half_area() >
                    node.children[i - 1].box.half_area() * (1 + 1e-6f));
      }
    for (size_t n = 0; n < plain.nodes.size() && n < by_area.nodes.size(); ++n)
      reordered += plain.nodes[n].children[0].box == by_area.nodes[n].children[0].box ? 0 : 1;
    CHECK(sorted);
    CHECK(reordered > 0);
  }
}

// [ch04-test-occluder-cost]
// A shadow ray stops at its first blocker, so what it costs to look through a node depends on
// the order of its children: a child that blocks every ray entering it spares the ones after
// it. Three children in the node's box [0,1]^3: a cheap one that cannot block, an expensive one
// that blocks surely, and a small one beside it that blocks a tenth of the rays entering it.
TEST_CASE("ch04: a child that surely blocks a shadow ray spares the children after it") {
  using sah::OccluderSummary;
  SahBuildOptions options;
  options.occluder_order = OccluderOrder::likely_blocker;
  const Box3f unit{{0, 0, 0}, {1, 1, 1}}, half{{0, 0, 0}, {1, 1, 0.5f}};  // half areas 3 and 2
  BuildTree<4>::Node node;
  node.num_children = 3;
  node.children[0] = {unit, 1, 0};  // inner children: the summaries below stand for them
  node.children[1] = {unit, 2, 0};
  node.children[2] = {half, 3, 0};
  const OccluderSummary empty{0.0, 1.0}, blocker{1.0, 10.0}, small{0.1, 2.0};  // {blocks, cost}
  std::array<OccluderSummary, 4> kids{empty, blocker, small, {}};
  const OccluderSummary s = sah::order_children<4>(node, kids, unit, options);
  // Scores, blocking chance over cost: the blocker 1 / 10, the small one 0.1 / 2, the empty
  // one 0: that order.
  CHECK(node.children[0].index == 2);
  CHECK(node.children[1].index == 3);
  CHECK(node.children[2].index == 1);
  // Every ray entering the node enters the blocker and stops there: only the node's own test
  // and the blocker's search remain, however much the others would cost.
  CHECK(s.cost == doctest::Approx(options.traversal_cost + 10.0));
  CHECK(s.blocks == 1.0);
  // Without the blocker, a ray enters the small child with chance 2/3 and is blocked there with
  // chance 0.1; only the others go on into the empty child.
  node.num_children = 2;
  node.children[0] = {unit, 1, 0};
  node.children[1] = {half, 3, 0};
  kids = {empty, small, {}, {}};
  const OccluderSummary t = sah::order_children<4>(node, kids, unit, options);
  CHECK(node.children[0].index == 3);
  const double enters_small = 2.0 / 3.0;
  CHECK(t.cost == doctest::Approx(options.traversal_cost + enters_small * 2.0 +
                                  (1.0 - enters_small * 0.1) * 1.0));
  CHECK(t.blocks == doctest::Approx(enters_small * 0.1));
  // A leaf's chance is its surface over its box's half area, capped at 1: a flat square box
  // holds half a square of triangle, so one such primitive blocks half the rays, four all.
  const PrimRef flat(Box3f({0, 0, 0}, {1, 1, 0}), 0);
  const std::vector<PrimRef> four(4, flat);
  CHECK(sah::leaf_summary(&flat, 1, flat.box(), options).blocks == doctest::Approx(0.5));
  CHECK(sah::leaf_summary(four.data(), 4, flat.box(), options).blocks == 1.0);
}
// [ch04-test-occluder-cost]

TEST_CASE_TEMPLATE("ch04: every ray reaches the triangle the brute-force oracle hits", W,
                   std::integral_constant<int, 2>, std::integral_constant<int, 4>,
                   std::integral_constant<int, 8>, std::integral_constant<int, 16>) {
  constexpr int N = W::value;
  for (const auto& scene : scenes()) {
    CAPTURE(scene.name);
    const std::vector<PrimRef> refs = make_prim_refs(scene.mesh);
    const BuildTree<N> tree = build_binned_sah<N>(refs);
    const std::vector<Ray> rays = test::mixed_rays(scene.mesh.bounds(), 200, 44);
    int hits = 0, unreached = 0;
    for (const Ray& ray : rays) {
      const Hit hit = test::brute_force_intersect(scene.mesh, ray);
      if (!hit.found()) continue;
      ++hits;
      unreached += test::reaches(tree, ray, hit.prim) ? 0 : 1;
    }
    CHECK(hits > 20);
    CHECK(unreached == 0);
  }
}
