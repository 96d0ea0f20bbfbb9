// Chapter 3: BVH4 and BVH8, every ISA and every trick configuration, against the brute-force
// oracle and against each other.
#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "02_bvh2/accel_test_support.h"
#include "02_bvh2/median_builder.h"
#include "03_bvh4/bvh4.h"
#include "03_bvh4/push_order.h"
#include "testing/sanitizer_build.h"

using namespace rtk;

namespace {

template <int N>
BVHN<N> build(const TriangleMesh& mesh, int max_leaf = 4) {
  return make_bvh<N>(build_median<N>(make_prim_refs(mesh), max_leaf), mesh);
}

template <int N>
std::vector<Hit> trace(Isa isa, const BVHN<N>& bvh, const Tricks& tricks, const std::vector<Ray>& rays,
                       TraversalStats* stats = nullptr) {
  std::vector<Hit> hits(rays.size());
  intersect(isa, bvh, tricks, rays, hits, stats);
  return hits;
}

template <int N>
std::vector<uint8_t> trace_occlusion(Isa isa, const BVHN<N>& bvh, const Tricks& tricks,
                                     const std::vector<Ray>& rays, TraversalStats* stats = nullptr) {
  std::vector<uint8_t> occ(rays.size(), 7);
  occluded(isa, bvh, tricks, rays, occ, stats);
  return occ;
}

/// The trick configurations the tests run: all of them, or under the sanitizers (50 to 100
/// times slower) all tricks on, all off and the one that changes what a box test answers.
std::vector<NamedTricks> tested_configs() {
  std::vector<NamedTricks> configs;
  for (const NamedTricks& c : kTrickConfigs)
    if (!test::kSanitizerBuild || c.name == "all" || c.name == "none" || c.name == "no_conservative_exits")
      configs.push_back(c);
  return configs;
}

}  // namespace

TEST_CASE_TEMPLATE("ch03: BVH4 and BVH8 agree with brute force for every ISA and trick set", W,
                   std::integral_constant<int, 4>, std::integral_constant<int, 8>,
                   std::integral_constant<int, 16>) {
  constexpr int N = W::value;
  for (const test::OracleCase& c : test::oracle_cases()) {
    for (int max_leaf : {1, 4}) {
      const BVHN<N> bvh = build<N>(c.mesh, max_leaf);
      for (Isa isa : supported_isas())
        for (const NamedTricks& config : tested_configs()) {
          const std::string what = "bvh" + std::to_string(N) + "/" + std::string(isa_name(isa)) + "/" +
                                   std::string(config.name) + "/leaf" + std::to_string(max_leaf);
          test::check_against_oracle(c, trace(isa, bvh, config.tricks, c.rays),
                                     trace_occlusion(isa, bvh, config.tricks, c.rays), what);
        }
    }
  }
}

namespace {

// Two traversal counts that differ by at most 1 % (and two, for counts near zero): the fused
// slab test enters a box the other one grazes now and then (one leaf in 2,598 on the soup).
bool close_counts(uint64_t a, uint64_t b) {
  return std::fabs(double(a) - double(b)) <= 0.01 * double(b) + 2.0;
}

/// A fused variant's statistics against the scalar kernel's: the same rays, close counts.
void check_close_stats(const TraversalStats& stats, const TraversalStats& ref) {
  CHECK(stats.rays == ref.rays);
  CHECK(close_counts(stats.nodes, ref.nodes));
  CHECK(close_counts(stats.leaves, ref.leaves));
  CHECK(close_counts(stats.primitives, ref.primitives));
  CHECK(close_counts(stats.culled, ref.culled));
}

}  // namespace

TEST_CASE_TEMPLATE("ch03: every ISA matches the scalar kernels bit for bit, statistics included", W,
                   std::integral_constant<int, 4>, std::integral_constant<int, 8>,
                   std::integral_constant<int, 16>) {
  constexpr int N = W::value;
  for (const test::OracleCase& c : test::oracle_cases()) {
    const BVHN<N> bvh = build<N>(c.mesh);
    for (const NamedTricks& config : tested_configs()) {
      TraversalStats ref_stats, ref_occ_stats;
      const std::vector<Hit> reference = trace(Isa::scalar, bvh, config.tricks, c.rays, &ref_stats);
      const std::vector<uint8_t> reference_occ =
          trace_occlusion(Isa::scalar, bvh, config.tricks, c.rays, &ref_occ_stats);
      // The ISAs that fuse multiply-adds (AVX2, AVX-512) compute a ray's slab distances in one
      // rounding (chapter 2's fused_offset), so they may enter, order and cull a few boxes
      // otherwise: their hits and occlusion must be the scalar kernel's, their statistics each
      // other's, and close to the scalar kernel's.
      const bool fused_boxes = config.tricks.conservative_exits && config.tricks.near_far_by_sign;
      std::optional<TraversalStats> fused_stats, fused_occ_stats;
      for (Isa isa : supported_isas()) {
        INFO("bvh" << N << " " << isa_name(isa) << " " << config.name << " on " << c.name);
        TraversalStats stats, occ_stats;
        CHECK(test::first_difference(trace(isa, bvh, config.tricks, c.rays, &stats), reference) == -1);
        CHECK(trace_occlusion(isa, bvh, config.tricks, c.rays, &occ_stats) == reference_occ);
        if (fused_boxes && (isa == Isa::avx2 || isa == Isa::avx512)) {
          if (!fused_stats) {
            fused_stats = stats;
            fused_occ_stats = occ_stats;
          }
          CHECK(stats == *fused_stats);
          CHECK(occ_stats == *fused_occ_stats);
          check_close_stats(stats, ref_stats);
          check_close_stats(occ_stats, ref_occ_stats);
        } else {
          CHECK(stats == ref_stats);
          CHECK(occ_stats == ref_occ_stats);
        }
        // The statistics mode changes nothing but the counting.
        CHECK(test::first_difference(trace(isa, bvh, config.tricks, c.rays), reference) == -1);
      }
      // The fast entry points are the "all tricks" configuration.
      if (config.tricks == Tricks{}) {
        for (Isa isa : supported_isas()) {
          std::vector<Hit> hits(c.rays.size());
          intersect(isa, bvh, c.rays, hits);
          std::vector<uint8_t> occ(c.rays.size());
          occluded(isa, bvh, c.rays, occ);
          CHECK(test::first_difference(hits, reference) == -1);
          CHECK(occ == reference_occ);
        }
      }
    }
  }
}

TEST_CASE_TEMPLATE("ch03: the tricks change the work, never the distance of the closest hit", W,
                   std::integral_constant<int, 4>, std::integral_constant<int, 8>,
                   std::integral_constant<int, 16>) {
  constexpr int N = W::value;
  // Random rays have no zero direction component: every box test is then free of NaN and the
  // min/max box test computes the same planes as the sign-selected one. The closest t is the
  // minimum over the triangles hit, whatever the order of visits; ties may name either triangle.
  for (const test::OracleCase& c : test::oracle_cases()) {
    const BVHN<N> bvh = build<N>(c.mesh);
    const std::vector<Ray> rays = test::random_rays(c.mesh.bounds(), 500, 31);
    const std::vector<Hit> all = trace(Isa::scalar, bvh, Tricks{}, rays);
    for (const NamedTricks& config : kTrickConfigs) {
      const std::vector<Hit> hits = trace(Isa::scalar, bvh, config.tricks, rays);
      for (size_t i = 0; i < rays.size(); ++i) {
        INFO(config.name << " on " << c.name << " ray " << i);
        CHECK(hits[i].found() == all[i].found());
        CHECK(hits[i].t == all[i].t);
      }
    }
  }
}

TEST_CASE_TEMPLATE("ch03: the statistics count what the traversal did", W,
                   std::integral_constant<int, 4>, std::integral_constant<int, 8>,
                   std::integral_constant<int, 16>) {
  constexpr int N = W::value;
  const test::OracleCase& c = test::oracle_cases()[1];  // the sphere
  const BVHN<N> bvh = build<N>(c.mesh);
  size_t valid = 0;
  for (const Ray& r : c.rays) valid += is_valid(r);
  TraversalStats all, no_cull, no_sort, none;
  trace(Isa::scalar, bvh, Tricks{}, c.rays, &all);
  trace(Isa::scalar, bvh, Tricks{.cull_at_pop = false}, c.rays, &no_cull);
  trace(Isa::scalar, bvh, Tricks{.sorted_push = false}, c.rays, &no_sort);
  trace(Isa::scalar, bvh, kTrickConfigs[kTrickConfigCount - 1].tricks, c.rays, &none);
  for (const TraversalStats* s : {&all, &no_cull, &no_sort, &none}) {
    CHECK(s->rays == valid);
    uint64_t visits = 0;
    for (uint64_t n : s->children_hit) visits += n;
    CHECK(visits == s->nodes);  // one histogram entry per node visit
    for (size_t k = N + 1; k < s->children_hit.size(); ++k) CHECK(s->children_hit[k] == 0);
    CHECK(s->nodes >= valid);  // every valid ray tests the root's children
  }
  // Culling skips work and counts what it skipped; without it nothing is skipped.
  CHECK(all.culled > 0);
  CHECK(no_cull.culled == 0);
  CHECK(all.nodes < no_cull.nodes);
  CHECK(all.leaves < no_cull.leaves);
  // Front-to-back order finds the closest hit sooner, so more is culled than in slot order.
  CHECK(all.nodes <= no_sort.nodes);
  // An occlusion ray stops at its first hit: fewer visits than the closest hit needs.
  TraversalStats occ;
  trace_occlusion(Isa::scalar, bvh, Tricks{}, c.rays, &occ);
  CHECK(occ.nodes < all.nodes);
  CHECK(occ.culled == 0);
}

// [ch03-test-push-order]
TEST_CASE("ch03: the branch-free orders of pushed children are the insertion sort's") {
  // Distances with ties, both zeros, negative entries (a ray starting behind the boxes' planes)
  // and infinity; every triple of them in every three of eight slots.
  const float values[] = {-2.0f, -0.0f, 0.0f, 0.5f, 1.0f, std::numeric_limits<float>::infinity()};
  SUBCASE("keys order by distance, then slot") {
    for (float a : values)
      for (float b : values)
        for (int i = 0; i < 8; ++i)
          for (int j = 0; j < 8; ++j)
            if (i != j) CHECK((push_key(a, i) < push_key(b, j)) == (a < b || (a == b && i < j)));
  }
  SUBCASE("three children") {
    NodeRef children[8];
    for (int s = 0; s < 8; ++s) children[s] = make_inner_ref(64 * size_t(s + 1));
    int checked = 0;
    for (int i0 = 0; i0 < 8; ++i0)
      for (int i1 = i0 + 1; i1 < 8; ++i1)
        for (int i2 = i1 + 1; i2 < 8; ++i2)
          for (float x : values)
            for (float y : values)
              for (float z : values) {
                float d[8] = {};
                d[i0] = x, d[i1] = y, d[i2] = z;
                BvhStackEntry expected[3] = {
                    {children[i0], x}, {children[i1], y}, {children[i2], z}};
                sort_pushed(expected, expected + 3);
                BvhStackEntry stack[3] = {};
                BvhStackEntry* sp = stack;
                const NodeRef next = push_three(children, d, i0, i1, i2, sp);
                CHECK(sp == stack + 2);
                CHECK(next == expected[2].ref);
                for (int k = 0; k < 2; ++k) {
                  CHECK(stack[k].ref == expected[k].ref);
                  // the distance cull-at-pop compares, the same float bit for bit
                  CHECK(std::bit_cast<uint32_t>(stack[k].dist) == std::bit_cast<uint32_t>(expected[k].dist));
                }
                ++checked;
              }
    CHECK(checked == 56 * 216);
  }
}
// [ch03-test-push-order]

TEST_CASE("ch03: a ray lying in a face plane of a box still finds the edge it hits there") {
  // With the sign-selected planes the 0 * inf = NaN of such a slab drops out of the max and min
  // chains. The min/max box test cannot order its operands for both planes at once and loses
  // some of these hits (edge hits, within the oracle's tolerance): one more reason for the trick.
  const TriangleMesh mesh = test::make_squares_and_speck();
  const std::vector<Ray> rays = test::face_plane_rays();
  auto check = [&](const auto& bvh) {
    for (Isa isa : supported_isas())
      for (const NamedTricks& config : kTrickConfigs) {
        if (!config.tricks.near_far_by_sign) continue;
        const std::vector<Hit> hits = trace(isa, bvh, config.tricks, rays);
        for (size_t i = 0; i < rays.size(); ++i) {
          INFO(isa_name(isa) << " " << config.name << " ray " << i);
          CHECK(hits[i].prim <= 5);
          CHECK(hits[i].t == 1.0f);
        }
        CHECK(trace_occlusion(isa, bvh, config.tricks, rays) == std::vector<uint8_t>(rays.size(), 1));
      }
  };
  check(build<4>(mesh, 1));
  check(build<8>(mesh, 1));
  check(build<16>(mesh, 1));
}

// [ch03-test-same-work]
TEST_CASE_TEMPLATE("ch03: five of the tricks change how the work is done, not which work", W,
                   std::integral_constant<int, 4>, std::integral_constant<int, 8>,
                   std::integral_constant<int, 16>) {
  // Early pop, the 1- and 2-hit paths, plane selection by sign and prefetching visit the same
  // nodes in the same order as their fallbacks (the general path pushes and sorts, then pops
  // the nearest), so the statistics must be identical. Random rays have no zero direction
  // component, where the min/max box test could differ. Visiting shadow rays' children in
  // stored order is for occlusion only: closest-hit rays must not notice it either.
  constexpr int N = W::value;
  for (const test::OracleCase& c : test::oracle_cases()) {
    const BVHN<N> bvh = build<N>(c.mesh);
    const std::vector<Ray> rays = test::random_rays(c.mesh.bounds(), 400, 32);
    TraversalStats all, all_occlusion;
    trace(Isa::scalar, bvh, Tricks{}, rays, &all);
    trace_occlusion(Isa::scalar, bvh, Tricks{}, rays, &all_occlusion);
    for (const Tricks& t : {Tricks{.near_far_by_sign = false}, Tricks{.early_pop = false},
                            Tricks{.one_hit_path = false}, Tricks{.two_hit_path = false},
                            Tricks{.prefetch_children = false}, Tricks{.shadow_rays_in_stored_order = false}}) {
      TraversalStats stats;
      trace(Isa::scalar, bvh, t, rays, &stats);
      INFO(c.name << " config " << kTrickConfigs[trick_config_index(t)].name);
      CHECK(stats == all);
      if (t.shadow_rays_in_stored_order) {
        TraversalStats occlusion;
        trace_occlusion(Isa::scalar, bvh, t, rays, &occlusion);
        CHECK(occlusion == all_occlusion);
      }
    }
  }
}
// [ch03-test-same-work]

TEST_CASE("ch03: unused child slots are never entered") {
  // Two triangles far apart, leaves of one: the root of a BVH8 uses 2 of its 8 slots.
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {10, 10, 10}, {11, 10, 10}, {10, 11, 10}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  const BVH8 bvh = build<8>(mesh, 1);
  REQUIRE(bvh.nodes.size() == 1);
  CHECK(bvh.nodes[0].children[2] == kEmptyLeaf);
  CHECK(bvh.nodes[0].lower_x[7] == std::numeric_limits<float>::infinity());
  // Rays in all eight octants with tfar = +inf, tnear = -inf, and with zero components, none
  // of which hits either triangle's box: no child may be hit, not even an unused one.
  std::vector<Ray> rays;
  for (int octant = 0; octant < 8; ++octant)
    for (float zero : {1.0f, 0.0f}) {
      Ray r;
      r.org = {5, -5, 6};
      r.dir = {octant & 1 ? -1.0f : 1.0f, (octant & 2 ? -1.0f : 1.0f) * zero, octant & 4 ? -1.0f : 1.0f};
      r.tnear = octant % 3 == 0 ? -std::numeric_limits<float>::infinity() : 0.0f;
      rays.push_back(r);
    }
  for (Isa isa : supported_isas())
    for (const NamedTricks& config : kTrickConfigs) {
      INFO(isa_name(isa) << " " << config.name);
      TraversalStats stats;
      for (const Hit& h : trace(isa, bvh, config.tricks, rays, &stats)) CHECK_FALSE(h.found());
      CHECK(stats.nodes == rays.size());
      CHECK(stats.children_hit[0] == rays.size());
      CHECK(stats.leaves == 0);
    }
}

TEST_CASE("ch03: invalid rays miss and leave the other rays alone") {
  const test::OracleCase& c = test::oracle_cases()[1];
  const BVH4 bvh4 = build<4>(c.mesh);
  const BVH8 bvh8 = build<8>(c.mesh);
  const std::vector<Ray> valid = test::random_rays(c.mesh.bounds(), 200, 78);
  std::vector<Ray> mixed;
  std::vector<Ray> invalid;
  for (const Ray& r : test::invalid_rays())
    if (!is_valid(r)) invalid.push_back(r);
  for (size_t i = 0; i < valid.size(); ++i) {
    mixed.push_back(invalid[i % invalid.size()]);
    mixed.push_back(valid[i]);
  }
  auto check = [&](const auto& bvh) {
    for (Isa isa : supported_isas())
      for (const NamedTricks& config : kTrickConfigs) {
        INFO(isa_name(isa) << " " << config.name);
        TraversalStats stats;
        const std::vector<Hit> alone = trace(isa, bvh, config.tricks, valid);
        const std::vector<Hit> together = trace(isa, bvh, config.tricks, mixed, &stats);
        const std::vector<uint8_t> occ_alone = trace_occlusion(isa, bvh, config.tricks, valid);
        const std::vector<uint8_t> occ_together = trace_occlusion(isa, bvh, config.tricks, mixed);
        CHECK(stats.rays == valid.size());  // invalid rays are not traversed
        int hits = 0;
        for (size_t i = 0; i < valid.size(); ++i) {
          CHECK(test::first_difference({alone[i]}, {together[2 * i + 1]}) == -1);
          CHECK(occ_alone[i] == occ_together[2 * i + 1]);
          CHECK_FALSE(together[2 * i].found());
          CHECK(occ_together[2 * i] == 0);
          hits += alone[i].found();
        }
        CHECK(hits > 100);
      }
  };
  check(bvh4);
  check(bvh8);
  check(build<16>(c.mesh));
}

TEST_CASE("ch03: node layout and what is refused") {
  TriangleMesh mesh;
  for (int i = 0; i < 3; ++i) {
    const float x = float(3 * i);
    const uint32_t first = uint32_t(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), {{x, 0, 0}, {x + 1, 0, 0}, {x, 2, 1}});
    mesh.triangles.push_back({first, first + 1, first + 2});
  }
  const BVH4 bvh = build<4>(mesh, 1);
  REQUIRE(bvh.nodes.size() == 1);
  const Node4& n = bvh.nodes[0];
  const float inf = std::numeric_limits<float>::infinity();
  // Children sorted by the median splits along x; the fourth slot is unused.
  CHECK(std::vector<float>(n.lower_x, n.lower_x + 4) == std::vector<float>{0, 3, 6, inf});
  CHECK(std::vector<float>(n.upper_x, n.upper_x + 4) == std::vector<float>{1, 4, 7, inf});
  CHECK(std::vector<float>(n.upper_y, n.upper_y + 4) == std::vector<float>{2, 2, 2, inf});
  CHECK(std::vector<float>(n.upper_z, n.upper_z + 4) == std::vector<float>{1, 1, 1, inf});
  CHECK(n.children[3] == kEmptyLeaf);
  CHECK(bvh.bytes() == sizeof(Node4) + 3 * sizeof(Triangle1));

  const std::vector<Ray> rays = test::random_rays(mesh.bounds(), 8, 1);
  std::vector<Hit> hits(rays.size());
  Tricks unusual;
  unusual.early_pop = unusual.cull_at_pop = false;  // two off at once: not compiled
  CHECK_THROWS_WITH_AS(intersect(best_isa(), bvh, unusual, rays, hits), doctest::Contains("no_near_far"),
                       std::invalid_argument);
  std::vector<uint8_t> short_occ(3);
  CHECK_THROWS_AS(occluded(best_isa(), bvh, rays, short_occ), std::invalid_argument);
  BVH4 other = bvh;
  other.leaves.layout = "triangle4i";
  CHECK_THROWS_AS(intersect(best_isa(), other, rays, hits), std::invalid_argument);
  // Too many children for the width, and a leaf too large to count.
  BuildTree<4> wide = build_median<4>(make_prim_refs(mesh), 1);
  wide.nodes[0].num_children = 5;
  CHECK_THROWS_AS(make_bvh<4>(wide, mesh), std::invalid_argument);
  const TriangleMesh soup = test::make_random_soup(100, 3);
  CHECK_THROWS_AS(make_bvh<8>(build_median<8>(make_prim_refs(soup), 40), soup), std::invalid_argument);
  // The empty scene.
  const BVH8 empty = make_bvh<8>(BuildTree<8>{}, TriangleMesh{});
  std::vector<Hit> none(rays.size());
  for (Isa isa : supported_isas()) {
    intersect(isa, empty, rays, none);
    for (const Hit& h : none) CHECK_FALSE(h.found());
  }
}
