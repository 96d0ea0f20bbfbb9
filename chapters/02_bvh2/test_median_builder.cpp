// Chapter 2: the median builder makes valid trees for every node width.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "02_bvh2/median_builder.h"
#include "testing/scenes.h"

using namespace rtk;

namespace {

// Why `tree` is not a valid median-built tree over the buildable references of `refs`, or "".
// Checked: each buildable reference's primitive sits in exactly one leaf; each box is exactly
// the union of what it holds (so children lie inside parents); leaves hold 1..max_leaf; nodes
// have 2..N children and come after their parents; a node with room left has only leaves.
template <int N>
std::string check_tree(const BuildTree<N>& tree, const std::vector<PrimRef>& refs, int max_leaf) {
  std::ostringstream err;
  std::vector<int> expected(refs.size(), 0), seen(refs.size(), 0);
  size_t buildable = 0;
  for (const PrimRef& r : refs)
    if (is_buildable(r)) ++expected[r.prim], ++buildable;
  if (tree.prim_ids.size() != buildable) return "prim_ids does not hold each buildable reference once";
  if (buildable == 0) return tree.empty() ? "" : "a tree over nothing must be empty";

  std::vector<int> visited(tree.nodes.size(), 0);
  // Returns the union of the boxes below `c`, checking the way down.
  auto walk = [&](auto&& self, const typename BuildTree<N>::Child& c, size_t parent) -> Box3f {
    Box3f box;
    if (c.is_leaf()) {
      if (c.leaf_count > uint32_t(max_leaf)) err << "leaf of " << c.leaf_count << "; ";
      if (size_t(c.index) + c.leaf_count > tree.prim_ids.size()) {
        err << "leaf past prim_ids; ";
        return box;
      }
      for (uint32_t i = c.index; i < c.index + c.leaf_count; ++i) {
        const uint32_t prim = tree.prim_ids[i];
        ++seen[prim];
        box.extend(refs[prim].box());
      }
    } else {
      if (c.index >= tree.nodes.size() || (parent != size_t(-1) && c.index <= parent)) {
        err << "node " << c.index << " does not follow its parent; ";
        return box;
      }
      ++visited[c.index];
      const auto& node = tree.nodes[c.index];
      if (node.num_children < 2 || node.num_children > N) err << "node with " << node.num_children << " children; ";
      for (int i = 0; i < node.num_children; ++i) {
        const auto& child = node.children[size_t(i)];
        if (node.num_children < N && !child.is_leaf()) err << "a node with room has an inner child; ";
        box.extend(self(self, child, c.index));
      }
    }
    if (!(box == c.box)) err << "a box is not the union of what it holds; ";
    return box;
  };
  walk(walk, tree.root, size_t(-1));
  for (size_t p = 0; p < refs.size(); ++p)
    if (seen[p] != expected[p]) err << "primitive " << p << " in " << seen[p] << " leaves; ";
  for (size_t n = 0; n < visited.size(); ++n)
    if (visited[n] != 1) err << "node " << n << " reached " << visited[n] << " times; ";
  return err.str();
}

template <int N>
void check_scene(const TriangleMesh& mesh, const char* name) {
  const std::vector<PrimRef> refs = make_prim_refs(mesh);
  for (int max_leaf : {1, 2, 4, 15}) {
    const BuildTree<N> tree = build_median<N>(refs, max_leaf);
    INFO("N=" << N << " scene " << name << " max_leaf " << max_leaf);
    CHECK(check_tree(tree, refs, max_leaf) == "");
    // A balanced tree: the depth grows with log_N of the leaf count, never faster than halving.
    const double leaves_needed = std::ceil(double(refs.size()) / max_leaf);
    CHECK(tree_depth(tree) <= int(std::ceil(std::log2(std::max(2.0, leaves_needed)))) + 1);
  }
}

}  // namespace

TEST_CASE_TEMPLATE("ch02: the median builder's trees hold every triangle once in tight boxes", T,
                   std::integral_constant<int, 2>, std::integral_constant<int, 4>,
                   std::integral_constant<int, 8>, std::integral_constant<int, 16>) {
  constexpr int N = T::value;
  TriangleMesh soup = test::make_random_soup(700, 3);
  test::add_degenerate_triangles(soup, 10, 4);
  check_scene<N>(soup, "soup");
  check_scene<N>(test::make_sphere(12, 20), "sphere");
  check_scene<N>(test::make_terrain(16, 5), "terrain");
  check_scene<N>(test::make_slivers(300, 6), "slivers");
  // Every centroid the same: the median still halves the count.
  TriangleMesh stack;
  stack.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  stack.triangles.assign(100, {0, 1, 2});
  check_scene<N>(stack, "identical");
}

TEST_CASE("ch02: the median builder fills a node before it goes deeper") {
  // 64 references, leaves of 1: a BVH4 is a complete tree of depth 3 (4^3 = 64 leaves).
  TriangleMesh soup = test::make_random_soup(64, 9);
  const std::vector<PrimRef> refs = make_prim_refs(soup);
  const BuildTree<4> tree = build_median<4>(refs, 1);
  CHECK(tree.nodes.size() == 1 + 4 + 16);
  CHECK(tree_depth(tree) == 3);
  for (const auto& node : tree.nodes) CHECK(node.num_children == 4);
  // The same input gives the same tree.
  const BuildTree<4> again = build_median<4>(refs, 1);
  CHECK(again.prim_ids == tree.prim_ids);
}

TEST_CASE("ch02: a triangle's reference is its box, or a NaN box whichever coordinate is not finite") {
  const TriangleMesh mesh = test::make_random_soup(10, 3);
  for (uint32_t i = 0; i < mesh.size(); ++i) {
    const PrimRef r = make_prim_ref(mesh, i);
    CHECK(r.prim == i);
    CHECK(r.box() == mesh.bounds(i));
    CHECK(is_buildable(r));
  }
  const float bad_values[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity()};
  for (const float bad : bad_values)
    for (int corner = 0; corner < 3; ++corner)
      for (int axis = 0; axis < 3; ++axis) {
        TriangleMesh m = mesh;
        m.vertices[m.triangles[4][size_t(corner)]][axis] = bad;
        const PrimRef r = make_prim_ref(m, 4);
        CHECK(r.prim == 4);
        CHECK_FALSE(is_buildable(r));
        CHECK(std::isnan(r.lower.x));
      }
}

TEST_CASE("ch02: the median builder's small and bad inputs") {
  const std::vector<PrimRef> none;
  CHECK(build_median<2>(none, 4).empty());
  CHECK_THROWS_AS(build_median<4>(none, 0), std::invalid_argument);

  TriangleMesh one;
  one.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  one.triangles = {{0, 1, 2}};
  const BuildTree<4> leaf = build_median<4>(make_prim_refs(one), 4);
  CHECK(leaf.root.is_leaf());
  CHECK(leaf.root.leaf_count == 1);
  CHECK(leaf.nodes.empty());
  CHECK(tree_depth(leaf) == 0);

  // A triangle with a NaN or infinite vertex cannot be placed: it is left out, not a crash.
  TriangleMesh bad = test::make_random_soup(20, 1);
  bad.vertices[4].y = std::numeric_limits<float>::quiet_NaN();
  bad.vertices[9].z = std::numeric_limits<float>::infinity();
  const std::vector<PrimRef> refs = make_prim_refs(bad);
  CHECK_FALSE(is_buildable(refs[1]));
  CHECK_FALSE(is_buildable(refs[3]));
  const BuildTree<2> tree = build_median<2>(refs, 2);
  CHECK(check_tree(tree, refs, 2) == "");
  CHECK(tree.prim_ids.size() == 18);

  // An index past the vertices is refused with the triangle's number.
  bad.triangles[7][2] = 1000;
  CHECK_THROWS_WITH_AS(make_prim_refs(bad), doctest::Contains("triangle 7"), std::invalid_argument);
}
