// Chapter 6: every layout with Möller-Trumbore, through chapter 2's BVH2 and chapter 3's BVH4
// and BVH8, against the brute-force oracle, ISA against ISA, layout against layout and width
// against width; what each layout costs.
#include <doctest/doctest.h>
#include <tbb/global_control.h>

#include <cstring>
#include <stdexcept>
#include <vector>

#include "06_layouts/layout_build.h"
#include "06_layouts/test_support_ch06.h"
#include "06_layouts/triangle_m.h"

using namespace rtk;

namespace {

template <int N>
void check_every_layout(const test::LayoutScene& scene) {
  const BuildTree<N> tree = test::sah_tree<N>(scene.mesh);
  for (const TriangleLayout layout : kAllLayouts) {
    CAPTURE(scene.name);
    CAPTURE(N);
    CAPTURE(layout_name(layout));
    const LayoutBVH<N> bvh = make_layout_bvh<N>(tree, scene.mesh, layout);
    test::check_every_isa(
        scene, [&](Isa isa, auto rays, auto hits) { intersect(isa, bvh, rays, hits); },
        [&](Isa isa, auto rays, auto blocked) { occluded(isa, bvh, rays, blocked); });
  }
}

/// Whether two layout BVHs hold the same bytes: nodes, leaf blocks, root and bounds. The
/// indexed layouts' blocks hold the address of their structure's own copy of the vertices,
/// which differs from structure to structure; their blocks are compared by size only (the
/// other tests trace them).
template <int N>
bool same_structure(const LayoutTree<N>& a, const LayoutTree<N>& b, bool indexed = false) {
  return a.root == b.root && a.depth == b.depth && a.bounds == b.bounds &&
         a.nodes.size() == b.nodes.size() &&
         (indexed ? a.leaves.bytes.size() == b.leaves.bytes.size()
                  : a.leaves.bytes == b.leaves.bytes) &&
         std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(a.nodes[0])) == 0;
}

template <int N>
void check_threads_make_the_same(const TriangleMesh& mesh) {
  const BuildTree<N> tree = test::sah_tree<N>(mesh);
  tbb::global_control allow_four(tbb::global_control::max_allowed_parallelism, 4);
  for (const TriangleLayout layout : kAllLayouts) {
    CAPTURE(N);
    CAPTURE(layout_name(layout));
    const bool indexed =
        layout == TriangleLayout::triangle1i || layout == TriangleLayout::triangle4i;
    const LayoutBVH<N> one = make_layout_bvh<N>(tree, mesh, layout, 1);
    for (const int threads : {2, 4})
      CHECK(
          same_structure<N>(make_layout_bvh<N>(tree, mesh, layout, threads).bvh, one.bvh, indexed));
    // And what chapters 2 and 3 make with their serial loop.
    if (layout == TriangleLayout::triangle8)
      CHECK(same_structure<N>(make_layout_tree<N, Triangle8Layout>(tree, mesh), one.bvh));
    if (layout == TriangleLayout::triangle1)
      CHECK(same_structure<N>(make_layout_tree<N, Triangle1Layout>(tree, mesh), one.bvh));
  }
}

}  // namespace

TEST_CASE("ch06: one, two and four threads make the same structure, byte for byte") {
  // Enough nodes for the parallel loop to cut them into many pieces.
  const TriangleMesh sphere = test::make_sphere(96, 192);
  check_threads_make_the_same<2>(sphere);
  check_threads_make_the_same<4>(sphere);
  check_threads_make_the_same<8>(sphere);
}

TEST_CASE("ch06: every layout agrees with the oracle through BVH2, every ISA bit for bit") {
  for (const test::LayoutScene& scene : test::layout_scenes()) check_every_layout<2>(scene);
}

TEST_CASE("ch06: every layout agrees with the oracle through BVH4, every ISA bit for bit") {
  for (const test::LayoutScene& scene : test::layout_scenes()) check_every_layout<4>(scene);
}

TEST_CASE("ch06: every layout agrees with the oracle through BVH8, every ISA bit for bit") {
  for (const test::LayoutScene& scene : test::layout_scenes()) check_every_layout<8>(scene);
}

// [ch06-test-same-hits]
TEST_CASE("ch06: every layout finds the same hits bit for bit") {
  // Same tree, same leaf order, the same float operations on the same inputs: whether the
  // edges are precomputed or computed per ray, and whether the block holds 1, 4 or 8
  // triangles, changes nothing in the answer, only in the time and the memory.
  for (const test::LayoutScene& scene : test::layout_scenes()) {
    const BuildTree<4> tree = test::sah_tree<4>(scene.mesh);
    std::vector<Hit> first;
    for (const TriangleLayout layout : kAllLayouts) {
      CAPTURE(scene.name);
      CAPTURE(layout_name(layout));
      const LayoutBVH<4> bvh = make_layout_bvh<4>(tree, scene.mesh, layout);
      std::vector<Hit> hits(scene.rays.size());
      intersect(best_isa(), bvh, scene.rays, hits);
      if (first.empty()) {
        first = hits;
        continue;
      }
      int differ = 0;
      for (size_t i = 0; i < hits.size(); ++i) differ += !test::same_bits(hits[i], first[i]);
      CHECK(differ == 0);
    }
  }
}
// [ch06-test-same-hits]

// [ch06-test-widths]
TEST_CASE("ch06: every layout finds the same hits through BVH2, BVH4 and BVH8") {
  // Different trees, visited in different orders; the closest-hit rule (chapter 2) makes the
  // answer independent of the order, so each width, with each layout, gives BVH4's bits.
  for (const test::LayoutScene& scene : test::layout_scenes())
    for (const TriangleLayout layout : kAllLayouts) {
      CAPTURE(scene.name);
      CAPTURE(layout_name(layout));
      const LayoutBVH<2> bvh2 = build_layout_bvh<2>(scene.mesh, layout, 1);
      const LayoutBVH<4> bvh4 = build_layout_bvh<4>(scene.mesh, layout, 1);
      const LayoutBVH<8> bvh8 = build_layout_bvh<8>(scene.mesh, layout, 1);
      const size_t n = scene.rays.size();
      std::vector<Hit> h2(n), h4(n), h8(n);
      std::vector<uint8_t> o2(n), o4(n);
      intersect(best_isa(), bvh2, scene.rays, h2);
      intersect(best_isa(), bvh4, scene.rays, h4);
      intersect(best_isa(), bvh8, scene.rays, h8);
      occluded(best_isa(), bvh2, scene.rays, o2);
      occluded(best_isa(), bvh4, scene.rays, o4);
      int differ = 0;
      for (size_t i = 0; i < n; ++i)
        differ += !test::same_bits(h2[i], h4[i]) || !test::same_bits(h8[i], h4[i]) || o2[i] != o4[i];
      CHECK(differ == 0);
    }
}
// [ch06-test-widths]

TEST_CASE("ch06: bytes per triangle") {
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle1) == 48);
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle4) == 52);
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle8) == 52);
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle1v) == 48);
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle4v) == 40);
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle1i) == 32);
  CHECK(leaf_bytes_per_triangle(TriangleLayout::triangle4i) == 20);
  // On a closed mesh (about two triangles per vertex), each layout with the tree its blocks
  // want (sah_options_for): the indexed blocks are the leanest in all, shared vertices
  // counted, and the precomputed ones the largest.
  const TriangleMesh sphere = test::make_sphere(64, 128);
  auto bytes = [&](TriangleLayout layout) {
    const LayoutBVH<4> bvh = build_layout_bvh<4>(sphere, layout, 1);
    // What bytes() reports is what the leaves hold: their blocks are allocated once, whole,
    // not grown leaf by leaf with spare capacity behind them.
    CHECK(bvh.bvh.leaves.bytes.capacity() == bvh.bvh.leaves.bytes.size());
    const double b = double(bvh.bytes()) / double(sphere.size());
    MESSAGE(layout_name(layout) << ": " << b << " bytes per triangle (BVH4 nodes included)");
    CHECK(b <= estimated_bytes_per_triangle(layout, 4));
    // The estimates for two and eight children hold too.
    const LayoutBVH<8> bvh8 = build_layout_bvh<8>(sphere, layout, 1);
    CHECK(double(bvh8.bytes()) / double(sphere.size()) <= estimated_bytes_per_triangle(layout, 8));
    CHECK(bvh8.bvh.leaves.bytes.capacity() == bvh8.bvh.leaves.bytes.size());
    const LayoutBVH<2> bvh2 = build_layout_bvh<2>(sphere, layout, 1);
    CHECK(bvh2.bvh.leaves.bytes.capacity() == bvh2.bvh.leaves.bytes.size());
    MESSAGE(layout_name(layout) << ": " << double(bvh2.bytes()) / double(sphere.size()) << " bytes per triangle (BVH2)");
    CHECK(double(bvh2.bytes()) / double(sphere.size()) <= estimated_bytes_per_triangle(layout, 2));
    return b;
  };
  const double t4i = bytes(TriangleLayout::triangle4i), t4v = bytes(TriangleLayout::triangle4v);
  const double t4 = bytes(TriangleLayout::triangle4), t1i = bytes(TriangleLayout::triangle1i);
  const double t1 = bytes(TriangleLayout::triangle1), t8 = bytes(TriangleLayout::triangle8);
  CHECK(t4i < t1i);
  CHECK(t4i < t4v);
  CHECK(t4v < t4);
  CHECK(t4 < t1);  // blocks of four need fewer nodes above them
  CHECK(t8 < t4);  // and blocks of eight, as full, fewer still
  CHECK(bytes(TriangleLayout::triangle1v) == t1);
}

TEST_CASE("ch06: the indexed layouts keep their own copy of the vertices") {
  TriangleMesh mesh = test::make_sphere(10, 20);
  const std::vector<Ray> rays = test::random_rays(mesh.bounds(), 100, 66);
  const BuildTree<8> tree = test::sah_tree<8>(mesh);
  const LayoutBVH<8> reference = make_layout_bvh<8>(tree, mesh, TriangleLayout::triangle1v);
  LayoutBVH<8> indexed = make_layout_bvh<8>(tree, mesh, TriangleLayout::triangle4i);
  mesh = TriangleMesh{};  // the original goes away
  const LayoutBVH<8> moved = std::move(indexed);
  std::vector<Hit> a(rays.size()), b(rays.size());
  intersect(best_isa(), reference, rays, a);
  intersect(best_isa(), moved, rays, b);
  for (size_t i = 0; i < rays.size(); ++i) CHECK(test::same_bits(a[i], b[i]));
}

TEST_CASE("ch06: mismatched spans are refused") {
  const TriangleMesh mesh = test::make_sphere(4, 8);
  const LayoutBVH<4> bvh = make_layout_bvh<4>(test::sah_tree<4>(mesh), mesh, TriangleLayout::triangle4);
  std::vector<Ray> rays(3);
  std::vector<Hit> hits(2);
  CHECK_THROWS_AS(intersect(Isa::scalar, bvh, rays, hits), std::invalid_argument);
}

// [ch06-test-default]
TEST_CASE("ch06: the default layout follows the ISA, and the memory budget") {
  CHECK(choose_default_layout(1000, Isa::sse4, 4) == TriangleLayout::triangle4);
  CHECK(choose_default_layout(1000, Isa::avx2, 8) == TriangleLayout::triangle8);
  CHECK(choose_default_layout(1000, Isa::avx512, 8) == TriangleLayout::triangle8);
  CHECK(choose_default_layout(1000, Isa::scalar, 4) == TriangleLayout::triangle8);
  // A hundred million triangles in 5 GiB: the fast layout (7 GB) would not fit, the lean one
  // (4.2 GB) does.
  const size_t gb = size_t(1) << 30;
  CHECK(choose_default_layout(100'000'000, Isa::avx2, 8, 5 * gb) == TriangleLayout::triangle4i);
  CHECK(choose_default_layout(100'000'000, Isa::avx2, 8, 64 * gb) == TriangleLayout::triangle8);
  // The estimate is the node width's own: 6.6 GB for BVH4's triangle8, 7 GB for BVH8's.
  const size_t between = 6'800'000'000;
  CHECK(choose_default_layout(100'000'000, Isa::avx2, 4, between) == TriangleLayout::triangle8);
  CHECK(choose_default_layout(100'000'000, Isa::avx2, 8, between) == TriangleLayout::triangle4i);
  // The estimates order the layouts as their blocks do.
  for (const int width : {4, 8})
    CHECK(estimated_bytes_per_triangle(TriangleLayout::triangle4i, width) <
          estimated_bytes_per_triangle(TriangleLayout::triangle4, width));
}
// [ch06-test-default]
