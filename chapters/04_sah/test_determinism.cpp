// Chapter 4: the same input gives the same tree, bit for bit and node for node, whatever the
// number of threads. Run under ThreadSanitizer as well (see chapter.md).
#include <doctest/doctest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "04_sah/build_sah.h"
#include "04_sah/tree_checks.h"
#include "testing/scenes.h"

namespace {

using namespace rtk;

bool same_stats(const SahBuildStats& a, const SahBuildStats& b) {
  return a.primitives == b.primitives && a.skipped == b.skipped && a.inner_nodes == b.inner_nodes &&
         a.leaves == b.leaves && a.large_jobs == b.large_jobs && a.medium_jobs == b.medium_jobs &&
         a.small_jobs == b.small_jobs && a.fallback_splits == b.fallback_splits &&
         a.rotations == b.rotations;
}

}  // namespace

// [ch04-test-determinism]
TEST_CASE_TEMPLATE("ch04: one, two and four threads build the same tree", W,
                   std::integral_constant<int, 2>, std::integral_constant<int, 4>,
                   std::integral_constant<int, 8>) {
  constexpr int N = W::value;
  // Large enough for large jobs (parallel partitions), medium jobs (tasks) and small ones.
  TriangleMesh soup = test::make_random_soup(int(2 * kLargeJobPrims + 3000), 31);
  test::add_degenerate_triangles(soup, 500, 32);
  const std::vector<PrimRef> refs = make_prim_refs(soup);
  SahBuildOptions options;
  options.threads = 1;
  SahBuildStats stats1, stats2, stats4;
  const BuildTree<N> one = build_binned_sah<N>(refs, options, &stats1);
  options.threads = 2;
  const BuildTree<N> two = build_binned_sah<N>(refs, options, &stats2);
  // More threads than this machine has cores: a different schedule again. TBB caps an arena at
  // the core count unless told otherwise.
  tbb::global_control allow_four(tbb::global_control::max_allowed_parallelism, 4);
  options.threads = 4;
  const BuildTree<N> four = build_binned_sah<N>(refs, options, &stats4);
  REQUIRE(stats1.large_jobs > 0);
  CHECK(test::identical(one, two));
  CHECK(test::identical(one, four));
  CHECK(same_stats(stats1, stats2));
  CHECK(same_stats(stats1, stats4));
  CHECK(test::check_tree(one, refs, options.max_leaf_size) == "");
}
// [ch04-test-determinism]

TEST_CASE_TEMPLATE("ch04: every ISA's binning builds the same tree", W, std::integral_constant<int, 4>,
                   std::integral_constant<int, 8>) {
  constexpr int N = W::value;
  const TriangleMesh soup = test::make_random_soup(int(kLargeJobPrims + 5000), 33);
  const std::vector<PrimRef> refs = make_prim_refs(soup);
  SahBuildOptions options;
  options.isa = Isa::scalar;
  SahBuildStats scalar_stats;
  const BuildTree<N> scalar_tree = build_binned_sah<N>(refs, options, &scalar_stats);
  for (Isa isa : supported_isas()) {
    CAPTURE(isa_name(isa));
    options.isa = isa;
    SahBuildStats stats;
    CHECK(test::identical(build_binned_sah<N>(refs, options, &stats), scalar_tree));
    CHECK(same_stats(stats, scalar_stats));
  }
}

TEST_CASE("ch04: determinism holds with every option, and in the caller's arena") {
  const std::vector<PrimRef> refs =
      make_prim_refs(test::make_terrain(140, 33));  // 39,200 triangles
  for (const bool rotations : {false, true})
    for (const OccluderOrder order :
         {OccluderOrder::off, OccluderOrder::largest_box, OccluderOrder::likely_blocker}) {
      CAPTURE(rotations);
      CAPTURE(int(order));
      SahBuildOptions options;
      options.rotations = rotations;
      options.occluder_order = order;
      options.threads = 1;
      const BuildTree<4> one = build_binned_sah<4>(refs, options);
      options.threads = 2;
      const BuildTree<4> two = build_binned_sah<4>(refs, options);
      options.threads = 0;
      const BuildTree<4> caller = build_binned_sah<4>(refs, options);
      CHECK(test::identical(one, two));
      CHECK(test::identical(one, caller));
    }
}

TEST_CASE("ch04: negative zeros do not make the bounds depend on the schedule") {
  // Half of the boxes touch the planes through 0 with -0 and half with +0; minimum and maximum
  // alone would pick one or the other depending on which thread merged what.
  TriangleMesh mesh = test::make_random_soup(int(kLargeJobPrims + 7000), 35);
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    if (i % 7 == 0 || mesh.vertices[i].x < 0.0f) mesh.vertices[i].x = (i % 2) ? -0.0f : 0.0f;
  const std::vector<PrimRef> refs = make_prim_refs(mesh);
  SahBuildOptions options;
  options.threads = 1;
  const BuildTree<4> one = build_binned_sah<4>(refs, options);
  options.threads = 2;
  const BuildTree<4> two = build_binned_sah<4>(refs, options);
  CHECK(test::identical(one, two));
  CHECK(std::signbit(one.root.box.lower.x) == false);
}

// [ch04-test-from-mesh]
TEST_CASE_TEMPLATE("ch04: a tree built from the mesh is the tree built from its references", W,
                   std::integral_constant<int, 4>, std::integral_constant<int, 8>) {
  constexpr int N = W::value;
  // Several blocks of references, zero-area triangles, and triangles with NaN and infinite
  // vertices in different blocks (left out, so the references must be squeezed together).
  TriangleMesh mesh = test::make_random_soup(int(2 * kLargeJobPrims + 3000), 37);
  test::add_degenerate_triangles(mesh, 500, 38);
  const float nan = std::numeric_limits<float>::quiet_NaN(),
              inf = std::numeric_limits<float>::infinity();
  for (const size_t t : {size_t(5), size_t(kPartitionBlockPrims + 7), mesh.size() - 1})
    mesh.vertices[mesh.triangles[t][1]] = Vec3f(nan, 0.0f, 0.0f);
  mesh.vertices[mesh.triangles[3 * kPartitionBlockPrims][0]].z = inf;
  const std::vector<PrimRef> refs = make_prim_refs(mesh);
  for (const int threads : {1, 2}) {
    SahBuildOptions options;
    options.threads = threads;
    SahBuildStats from_refs, from_mesh;
    const BuildTree<N> a = build_binned_sah<N>(refs, options, &from_refs);
    const BuildTree<N> b = build_binned_sah<N>(mesh, options, &from_mesh);
    CHECK(from_mesh.skipped == 4);
    CHECK(test::check_tree(b, refs, options.max_leaf_size) == "");
    CHECK(test::identical(a, b));
    CHECK(same_stats(from_refs, from_mesh));
  }
}

TEST_CASE("ch04: a vertex index out of range is refused, naming the first such triangle") {
  TriangleMesh mesh = test::make_random_soup(int(3 * kPartitionBlockPrims), 39);
  const uint32_t past = uint32_t(mesh.vertices.size());
  // The later block's triangle may well be seen first on two threads; the message is the same.
  mesh.triangles[2 * kPartitionBlockPrims + 1][2] = past + 5;
  mesh.triangles[kPartitionBlockPrims + 3][0] = past;
  std::string expected;
  try {
    make_prim_refs(mesh);
  } catch (const std::invalid_argument& e) {
    expected = e.what();
  }
  REQUIRE(expected.find("triangle " + std::to_string(kPartitionBlockPrims + 3)) == 0);
  for (const int threads : {1, 2}) {
    SahBuildOptions options;
    options.threads = threads;
    CHECK_THROWS_WITH_AS(build_binned_sah<8>(mesh, options), expected.c_str(), std::invalid_argument);
  }
}
// [ch04-test-from-mesh]
