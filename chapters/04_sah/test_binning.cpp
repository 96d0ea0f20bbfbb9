// Chapter 4: binning, the sweep, and the one-pass partition (serial and parallel).
#include <doctest/doctest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "04_sah/bin_kernels.h"
#include "04_sah/binning.h"
#include "04_sah/partition.h"
#include "testing/scenes.h"

namespace {

using namespace rtk;
using namespace rtk::sah;

PrimRef box_ref(Vec3f lower, Vec3f upper, uint32_t id) { return PrimRef(Box3f(lower, upper), id); }

bool same_bins(const Bins& a, const Bins& b) {
  if (a.num_bins != b.num_bins) return false;
  for (int axis = 0; axis < 3; ++axis)
    if (std::memcmp(a.bin[axis], b.bin[axis], sizeof(Bin) * size_t(a.num_bins)) != 0) return false;
  return true;
}

/// The centroid bounds' mapping with `n` bins, and every reference binned with it.
struct Binned {
  BinMapping map;
  std::unique_ptr<Bins> bins;
};
Binned bin_all(const std::vector<PrimRef>& refs, int n) {
  Box3f cent;
  for (const auto& r : refs) cent.extend(centroid(r));
  Binned out{BinMapping(cent, n), std::make_unique<Bins>()};
  out.bins->reset(n);
  bin_prims(refs.data(), uint32_t(refs.size()), out.map, *out.bins, best_isa());
  return out;
}

}  // namespace

TEST_CASE("ch04: the bin mapping covers the centroid bounds and refuses degenerate axes") {
  const Box3f cent({-1, 2, 5}, {3, 2, 5.5f});
  const BinMapping map(cent, 32);
  CHECK(map.splittable(0));
  CHECK_FALSE(map.splittable(1));  // no extent
  CHECK(map.splittable(2));
  CHECK(map.bin(cent.lower.x, 0) == 0);
  CHECK(map.bin(cent.upper.x, 0) == 31);
  CHECK(map.bin(1.0f, 0) == 16);
  CHECK(map.bin(2.0f, 1) == 0);
  // Extents that overflow, or a scale that does, cannot be binned.
  const BinMapping huge(Box3f({-3e38f, 0, 0}, {3e38f, 1e-45f, 1}), 32);
  CHECK_FALSE(huge.splittable(0));
  CHECK_FALSE(huge.splittable(1));
  CHECK(huge.splittable(2));
}

TEST_CASE("ch04: small sets get fewer bins, never fewer than two nor more than asked") {
  CHECK(bins_for(0, 32) == 2);
  CHECK(bins_for(1, 32) == 2);
  CHECK(bins_for(5, 32) == 5);   // one per primitive while that is below 4 + n / 4
  CHECK(bins_for(16, 32) == 8);  // 4 + 16 / 4
  CHECK(bins_for(100, 32) == 29);
  CHECK(bins_for(1000, 32) == 32);
  CHECK(bins_for(1000, 64) == 64);
  CHECK(bins_for(1000, 7) == 7);
}

TEST_CASE("ch04: the vector and the scalar bin computations agree") {
  // Binning uses bins() (all axes at once), partitioning bin() (one axis): a primitive must
  // land on the same side in both, or the children's boxes would not bound their primitives.
  const std::vector<PrimRef> refs = make_prim_refs(test::make_random_soup(2000, 3));
  Box3f cent;
  for (const auto& r : refs) cent.extend(centroid(r));
  for (const int n : {2, 7, 32, kMaxSahBins}) {
    const BinMapping map(cent, n);
    bool same = true;
    for (const auto& r : refs) {
      const Vec3f c = centroid(r);
      const Ints4 v = map.bins(Lanes4{c.x, c.y, c.z, 0.0f});
      for (int axis = 0; axis < 3; ++axis) same &= v[axis] == map.bin(c[axis], axis);
      same &= v[0] >= 0 && v[0] < n;
    }
    CHECK(same);
  }
}

TEST_CASE("ch04: the sweep finds the gap between two clusters, priced analytically") {
  // Ten unit cubes at x in [0, 1] and ten at x in [10, 11]: the best split separates them, and
  // costs area * count on each side: 3 * 10 (a unit cube has half area 3) twice.
  std::vector<PrimRef> refs;
  for (uint32_t i = 0; i < 10; ++i) refs.push_back(box_ref({0, 0, 0}, {1, 1, 1}, i));
  for (uint32_t i = 10; i < 20; ++i) refs.push_back(box_ref({10, 0, 0}, {11, 1, 1}, i));
  const auto [map, bins] = bin_all(refs, 32);
  const Split s = find_best_split(*bins, map);
  REQUIRE(s.valid());
  CHECK(s.axis == 0);
  CHECK(s.left_count == 10);
  CHECK(s.cost == doctest::Approx(60.0));
  CHECK(s.left_bounds == Box3f({0, 0, 0}, {1, 1, 1}));
  CHECK(s.right_bounds == Box3f({10, 0, 0}, {11, 1, 1}));
  CHECK(s.left_centroids == Box3f({0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}));
}

TEST_CASE("ch04: a leaf tested in blocks is priced by its blocks") {
  // Five unit cubes at x in [0, 1] and three at [10, 11]: one border separates them. Priced by
  // count it costs 3 * 5 + 3 * 3; in blocks of four, one block of three and two of five.
  std::vector<PrimRef> refs;
  for (uint32_t i = 0; i < 5; ++i) refs.push_back(box_ref({0, 0, 0}, {1, 1, 1}, i));
  for (uint32_t i = 5; i < 8; ++i) refs.push_back(box_ref({10, 0, 0}, {11, 1, 1}, i));
  const auto [map, bins] = bin_all(refs, 8);
  CHECK(find_best_split(*bins, map).cost == doctest::Approx(24.0));
  CHECK(find_best_split(*bins, map, 4).cost == doctest::Approx(9.0));
  CHECK(find_best_split(*bins, map, 8).cost == doctest::Approx(6.0));
}

TEST_CASE("ch04: the sweep finds the cheapest border, by count or by blocks, as brute force does") {
  const std::vector<PrimRef> refs = make_prim_refs(test::make_random_soup(300, 5));
  for (const int n : {5, 16, 32}) {
    const auto [map, bins] = bin_all(refs, n);
    for (const int block : {1, 4, 8, 16}) {
      CAPTURE(n);
      CAPTURE(block);
      // Every border of every axis priced in double precision from the bins.
      double cheapest = std::numeric_limits<double>::infinity();
      for (int axis = 0; axis < 3; ++axis)
        for (int i = 1; i < n; ++i) {
          const uint32_t l = bin_count(*bins, axis, 0, i), r = bin_count(*bins, axis, i, n);
          if (l == 0 || r == 0) continue;
          cheapest = std::min(cheapest,
                              half_area(bin_bounds(*bins, axis, 0, i)) * leaf_tests(l, block) +
                                  half_area(bin_bounds(*bins, axis, i, n)) * leaf_tests(r, block));
        }
      const Split s = find_best_split(*bins, map, block);
      REQUIRE(s.valid());
      // The sweep compares in float; what it picks is within float rounding of the minimum.
      CHECK(s.cost == doctest::Approx(cheapest).epsilon(1e-5));
    }
  }
}

/// The border the sweep must choose, priced one border at a time in the sweep's own float
/// arithmetic: each side's half area as (dx dy + dy dz) + dz dx, times its tests, the two sides
/// summed; the cheapest, the lowest axis and then the lowest border among equals. For sets whose
/// coordinates stay below 2^40, which the sweep prices without scaling.
std::pair<int, int> cheapest_border_in_float(const Bins& bins, const BinMapping& map, int block) {
  const int n = bins.num_bins;
  const auto side_cost = [&](int axis, int first, int last) {
    const Box3f b = bin_bounds(bins, axis, first, last);
    const float dx = b.upper.x - b.lower.x, dy = b.upper.y - b.lower.y, dz = b.upper.z - b.lower.z;
    return ((dx * dy + dy * dz) + dz * dx) * float(leaf_tests(bin_count(bins, axis, first, last), block));
  };
  float best = std::numeric_limits<float>::infinity();
  std::pair<int, int> choice{-1, 0};
  for (int axis = 0; axis < 3; ++axis) {
    if (!map.splittable(axis)) continue;
    for (int i = 1; i < n; ++i) {
      if (bin_count(bins, axis, 0, i) == 0 || bin_count(bins, axis, i, n) == 0) continue;
      const float cost = side_cost(axis, 0, i) + side_cost(axis, i, n);
      if (cost < best) best = cost, choice = {axis, i};
    }
  }
  return choice;
}

TEST_CASE("ch04: the sweep chooses the border a scalar pricing in its own float arithmetic chooses") {
  // Soups of several sizes and spreads, and a mesh whose many equal costs (a regular grid) test
  // the rule among equals.
  std::vector<std::vector<PrimRef>> sets;
  for (const int seed : {1, 2, 3})
    sets.push_back(make_prim_refs(test::make_random_soup(40 * seed * seed, uint64_t(seed))));
  sets.push_back(make_prim_refs(test::make_terrain(8, 1)));
  for (const auto& refs : sets)
    for (const int n : {2, 5, 16, 32}) {
      const auto [map, bins] = bin_all(refs, n);
      for (const int block : {1, 4, 8}) {
        CAPTURE(refs.size());
        CAPTURE(n);
        CAPTURE(block);
        const Split s = find_best_split(*bins, map, block);
        const auto [axis, pos] = cheapest_border_in_float(*bins, map, block);
        CHECK(s.axis == axis);
        if (s.valid()) CHECK(s.pos == pos);
      }
    }
}

TEST_CASE("ch04: the sweep chooses the same border for a set scaled by a power of two") {
  // Past 2^40 the sweep scales the coordinates down by a power of two before pricing; scaling is
  // exact, so a set and its copy scaled by 2^100 (coordinates near 1e30) must split alike.
  const std::vector<PrimRef> refs = make_prim_refs(test::make_random_soup(300, 7));
  std::vector<PrimRef> scaled;
  for (const PrimRef& r : refs) {
    scaled.push_back(box_ref(r.lower * 0x1p100f, r.upper * 0x1p100f, r.prim));
  }
  for (const int n : {5, 32})
    for (const int block : {1, 8}) {
      CAPTURE(n);
      CAPTURE(block);
      const auto [map, bins] = bin_all(refs, n);
      const auto [scaled_map, scaled_bins] = bin_all(scaled, n);
      const Split s = find_best_split(*bins, map, block), t = find_best_split(*scaled_bins, scaled_map, block);
      REQUIRE(s.valid());
      CHECK(t.axis == s.axis);
      CHECK(t.pos == s.pos);
      CHECK(t.left_count == s.left_count);
    }
}

TEST_CASE("ch04: the sweep finds no split when all centroids coincide") {
  std::vector<PrimRef> refs;
  for (uint32_t i = 0; i < 8; ++i) refs.push_back(box_ref(Vec3f(-float(i)), Vec3f(float(i)), i));
  const auto [map, bins] = bin_all(refs, 8);
  CHECK_FALSE(find_best_split(*bins, map).valid());
}

TEST_CASE("ch04: a split plane's left limit is the least float binned at or above its border") {
  // Mappings over ordinary, offset, tiny and huge ranges; the last two put the border's float
  // far from the limit (1e30 absorbs small coordinates), which the walk leaves to bisection.
  const Box3f ranges[] = {
      {Vec3f(0.0f), Vec3f(1.0f)},
      {Vec3f(-3.7f, 100.25f, -1e-3f), Vec3f(5.1f, 100.5f, 2e-3f)},
      {Vec3f(1e-30f), Vec3f(3e-30f)},
      {Vec3f(-1e30f), Vec3f(1e30f)},
      {Vec3f(-1e38f, -3e38f, 0.0f), Vec3f(2e38f, -1e38f, 3e38f)},
  };
  std::mt19937 rng(5);
  int planes = 0;
  for (const Box3f& range : ranges)
    for (const int bins : {2, 5, 32, 64}) {
      const BinMapping map(range, bins);
      for (int axis = 0; axis < 3; ++axis) {
        if (!map.splittable(axis)) continue;
        for (int pos = 1; pos < bins; ++pos) {
          const SplitPlane plane{&map, axis, pos};
          const float limit = plane.left_limit();
          const float before = std::nextafter(limit, -std::numeric_limits<float>::infinity());
          CHECK(map.bin(limit, axis) >= pos);
          CHECK(map.bin(before, axis) < pos);
          // And for coordinates around it and across the range, the comparison is the bin's.
          std::uniform_real_distribution<float> across(range.lower[axis], range.upper[axis]);
          float up = limit, down = limit;
          for (int k = 0; k < 16; ++k) {
            up = std::nextafter(up, std::numeric_limits<float>::infinity());
            down = std::nextafter(down, -std::numeric_limits<float>::infinity());
            const float c = across(rng);
            CHECK(map.bin(up, axis) >= pos);
            CHECK(map.bin(down, axis) < pos);
            CHECK((c < limit) == (map.bin(c, axis) < pos));
          }
          ++planes;
        }
      }
    }
  CHECK(planes > 400);
}

TEST_CASE("ch04: one-pass partition sends each primitive to its side and bins it there") {
  const TriangleMesh mesh = test::make_random_soup(3000, 7);
  std::vector<PrimRef> refs = make_prim_refs(mesh);
  const auto [map, bins] = bin_all(refs, 32);
  const Split s = find_best_split(*bins, map);
  REQUIRE(s.valid());

  const BinMapping left_map(s.left_centroids, 32), right_map(s.right_centroids, 32);
  auto left = std::make_unique<Bins>(), right = std::make_unique<Bins>();
  left->reset(32);
  right->reset(32);
  const SplitPlane plane{&map, s.axis, s.pos};
  const uint32_t mid = partition_and_bin(refs.data(), uint32_t(refs.size()), plane,
                                         {&left_map, left.get(), &right_map, right.get()}, best_isa());
  CHECK(mid == s.left_count);
  for (uint32_t i = 0; i < refs.size(); ++i) CHECK(plane.goes_left(refs[i]) == (i < mid));
  // The bins filled in passing equal bins filled by separate passes over each side.
  auto left2 = std::make_unique<Bins>(), right2 = std::make_unique<Bins>();
  left2->reset(32);
  right2->reset(32);
  bin_prims(refs.data(), mid, left_map, *left2, best_isa());
  bin_prims(refs.data() + mid, uint32_t(refs.size()) - mid, right_map, *right2, best_isa());
  CHECK(same_bins(*left, *left2));
  CHECK(same_bins(*right, *right2));
  CHECK(bin_bounds(*left, 0, 0, 32) == s.left_bounds);
  CHECK(bin_centroid_bounds(*right, 1, 0, 32) == s.right_centroids);
}

TEST_CASE(
    "ch04: the parallel partition gives the serial bins and the same layout for any thread count") {
  // Enough primitives for several blocks, with a block border falling mid-way.
  const uint32_t n = 5 * kPartitionBlockPrims + 123;
  const TriangleMesh mesh = test::make_random_soup(int(n), 11);
  const std::vector<PrimRef> input = make_prim_refs(mesh);
  Box3f cent;
  for (const auto& r : input) cent.extend(centroid(r));
  const BinMapping map(cent, 32);
  const SplitPlane plane{&map, 1, 13};
  Box3f lc, rc;
  for (const auto& r : input) (plane.goes_left(r) ? lc : rc).extend(centroid(r));
  const BinMapping left_map(lc, 32), right_map(rc, 32);

  auto run = [&](int threads, std::vector<PrimRef>& refs, Bins& left, Bins& right) {
    refs = input;
    tbb::task_arena arena(threads);
    return arena.execute([&] {
      return parallel_partition_and_bin(refs.data(), n, plane,
                                        {&left_map, &left, &right_map, &right}, best_isa());
    });
  };
  // Allow four threads on a machine with fewer cores (TBB caps arenas at the core count).
  tbb::global_control allow_four(tbb::global_control::max_allowed_parallelism, 4);
  std::vector<PrimRef> one, two, four;
  auto l1 = std::make_unique<Bins>(), r1 = std::make_unique<Bins>();
  auto l2 = std::make_unique<Bins>(), r2 = std::make_unique<Bins>();
  auto l4 = std::make_unique<Bins>(), r4 = std::make_unique<Bins>();
  const uint32_t mid1 = run(1, one, *l1, *r1);
  const uint32_t mid2 = run(2, two, *l2, *r2);
  const uint32_t mid4 = run(4, four, *l4, *r4);
  CHECK(mid1 == mid2);
  CHECK(mid1 == mid4);
  CHECK(std::memcmp(one.data(), two.data(), n * sizeof(PrimRef)) == 0);
  CHECK(std::memcmp(one.data(), four.data(), n * sizeof(PrimRef)) == 0);
  CHECK(same_bins(*l1, *l2));
  CHECK(same_bins(*r1, *r4));

  // Against the serial partition: the same sides, bins and multiset of references.
  std::vector<PrimRef> serial = input;
  auto ls = std::make_unique<Bins>(), rs = std::make_unique<Bins>();
  ls->reset(32);
  rs->reset(32);
  const uint32_t mids =
      partition_and_bin(serial.data(), n, plane, {&left_map, ls.get(), &right_map, rs.get()},
                        best_isa());
  CHECK(mids == mid1);
  CHECK(same_bins(*ls, *l1));
  CHECK(same_bins(*rs, *r1));
  bool sides_ok = true;
  std::vector<int> count(n, 0);
  for (uint32_t i = 0; i < n; ++i) {
    sides_ok &= plane.goes_left(one[i]) == (i < mid1);
    ++count[one[i].prim];
  }
  CHECK(sides_ok);
  CHECK(std::count(count.begin(), count.end(), 1) == std::ptrdiff_t(n));
}

// [ch04-test-bin-count]
TEST_CASE("ch04: a bin counts its primitives in the spare lane of its lower corner, on every ISA") {
  TriangleMesh mesh = test::make_random_soup(2000, 43);
  test::add_degenerate_triangles(mesh, 100, 44);
  const std::vector<PrimRef> refs = make_prim_refs(mesh);
  const uint32_t n = uint32_t(refs.size());
  Box3f cent;
  for (const auto& r : refs) cent.extend(centroid(r));
  const BinMapping map(cent, 16);
  for (Isa isa : supported_isas()) {
    CAPTURE(isa_name(isa));
    // Two halves binned apart and merged count what one pass over all of them counts.
    auto bins = std::make_unique<Bins>(), half = std::make_unique<Bins>();
    bins->reset(16);
    half->reset(16);
    CHECK(bins->bin[1][5].count() == 0);
    RTK_PICK_ISA(isa, bin_prims)(refs.data(), n / 2, map, *bins);
    RTK_PICK_ISA(isa, bin_prims)(refs.data() + n / 2, n - n / 2, map, *half);
    bins->merge(*half);
    for (int axis = 0; axis < 3; ++axis) {
      CAPTURE(axis);
      std::vector<uint32_t> expected(16, 0);
      for (const PrimRef& r : refs) ++expected[size_t(map.bin(centroid(r)[axis], axis))];
      for (int i = 0; i < 16; ++i) {
        CHECK(bins->bin[axis][i].count() == expected[size_t(i)]);
        // A normal float, so that whole-register float operations never meet a subnormal.
        CHECK(std::isnormal(bins->bin[axis][i].lower[3]));
      }
      CHECK(bin_count(*bins, axis, 0, 16) == n);
    }
  }
}
// [ch04-test-bin-count]

// [ch04-test-bin-kernels]
TEST_CASE("ch04: every ISA's binning passes fill the scalar variant's bins and order") {
  // Real boxes and corner cases: degenerate triangles (flat boxes, equal centroids), zeros
  // (+0 lower corners, whose negated upper corners are -0) and a huge coordinate.
  TriangleMesh mesh = test::make_random_soup(3000, 41);
  test::add_degenerate_triangles(mesh, 200, 42);
  std::vector<PrimRef> input = make_prim_refs(mesh);
  input.push_back(box_ref({0, 0, 0}, {0, 0, 0}, 90000));
  input.push_back(box_ref({-1e30f, 0, 0}, {-1e29f, 1, 1}, 90001));
  const uint32_t n = uint32_t(input.size());
  Box3f cent;
  for (const auto& r : input) cent.extend(centroid(r));
  const BinMapping map(cent, 32);
  Bins scalar_bins;
  scalar_bins.reset(32);
  scalar::bin_prims(input.data(), n, map, scalar_bins);
  const Split s = find_best_split(scalar_bins, map);
  REQUIRE(s.valid());
  const SplitPlane plane{&map, s.axis, s.pos};
  const BinMapping left_map(s.left_centroids, 16), right_map(s.right_centroids, 24);
  auto partition = [&](auto kernel, std::vector<PrimRef>& refs, Bins& left, Bins& right) {
    refs = input;
    left.reset(left_map.num_bins);
    right.reset(right_map.num_bins);
    return kernel(refs.data(), n, plane, ChildBins{&left_map, &left, &right_map, &right});
  };
  std::vector<PrimRef> scalar_refs;
  auto scalar_left = std::make_unique<Bins>(), scalar_right = std::make_unique<Bins>();
  const uint32_t scalar_mid =
      partition(scalar::partition_and_bin, scalar_refs, *scalar_left, *scalar_right);
  CHECK(scalar_mid == s.left_count);
  for (Isa isa : supported_isas()) {
    CAPTURE(isa_name(isa));
    auto bins = std::make_unique<Bins>();
    bins->reset(32);
    RTK_PICK_ISA(isa, bin_prims)(input.data(), n, map, *bins);
    CHECK(same_bins(*bins, scalar_bins));
    std::vector<PrimRef> refs;
    auto left = std::make_unique<Bins>(), right = std::make_unique<Bins>();
    CHECK(partition(RTK_PICK_ISA(isa, partition_and_bin), refs, *left, *right) == scalar_mid);
    CHECK(std::memcmp(refs.data(), scalar_refs.data(), n * sizeof(PrimRef)) == 0);
    CHECK(same_bins(*left, *scalar_left));
    CHECK(same_bins(*right, *scalar_right));
  }
}
// [ch04-test-bin-kernels]
