// Comparing hits: planted differences are found and counted by kind.
#include <doctest/doctest.h>

#include <limits>

#include "replay/compare.h"

TEST_CASE("io: compare finds planted hit differences") {
  std::vector<rtk::Hit> a(100);
  for (uint32_t i = 0; i < 100; ++i)
    if (i % 4 != 0) a[i] = {1.0f + float(i), 0.1f, 0.2f, i};  // every fourth ray misses
  std::vector<rtk::Hit> b = a;
  const rtk::HitComparison same = rtk::compare_hit_arrays(a, b);
  CHECK(same.agree() == 100);
  CHECK(same.both_miss == 25);
  CHECK(same.max_t_error == 0.0);

  b[1].t *= 1.0f + 1e-6f;   // within the tolerance: agrees
  b[2].t *= 1.01f;          // same prim, t off by 1%
  b[3].prim = 7;            // another prim at the same t (a tie)
  b[5] = rtk::Hit{};        // b misses
  b[8] = {3.0f, 0, 0, 99};  // b hits where a missed
  b[9] = {2.0f, 0, 0, 77};  // another prim at another t
  const rtk::HitComparison c = rtk::compare_hit_arrays(a, b, 1e-4, 3);
  CHECK(c.rays == 100);
  CHECK(c.t_mismatch == 1);
  CHECK(c.only_a_hit == 1);
  CHECK(c.only_b_hit == 1);
  CHECK(c.other_prim == 2);
  CHECK(c.other_prim_same_t == 1);
  CHECK(c.differ() == 5);
  CHECK(c.agree_percent() == doctest::Approx(95.0));
  CHECK(c.max_t_error == doctest::Approx(0.01 / 1.01).epsilon(1e-3));  // relative: t >= 1 here
  CHECK(c.first_differences == std::vector<size_t>{2, 3, 5});

  b[1].t = std::numeric_limits<float>::quiet_NaN();  // a NaN distance never agrees
  CHECK(rtk::compare_hit_arrays(a, b).t_mismatch == 2);
}

TEST_CASE("io: compare scales the t tolerance with the origin when it has the rays") {
  // A short hit from an origin far from 0: t's digits are not where the error is.
  std::vector<rtk::Ray> rays(1);
  rays[0].org = {100, 0, 0};
  rays[0].dir = {0, 0, 2};  // |org| / |dir| = 50
  const std::vector<rtk::Hit> a = {{0.01f, 0, 0, 3}};
  const std::vector<rtk::Hit> b = {{0.0125f, 0, 0, 3}};  // off by 0.0025 = 5e-5 of 50
  CHECK(rtk::compare_hit_arrays(a, b, 1e-4).t_mismatch == 1);         // scale max(|t|, 1) = 1
  CHECK(rtk::compare_hit_arrays(a, b, 1e-4, 10, rays).agree() == 1);  // scale 50
  CHECK(rtk::compare_hit_arrays(a, b, 1e-4, 10, rays).max_t_error == doctest::Approx(5e-5).epsilon(1e-3));
  CHECK_THROWS(rtk::compare_hit_arrays(a, b, 1e-4, 10, std::vector<rtk::Ray>(2)));
}

TEST_CASE("io: compare finds planted occlusion differences") {
  std::vector<uint8_t> a = {0, 1, 1, 0, 1, 0};
  std::vector<uint8_t> b = {0, 1, 0, 0, 1, 1};
  const rtk::OcclusionComparison c = rtk::compare_occlusion_arrays(a, b);
  CHECK(c.both_blocked == 2);
  CHECK(c.both_free == 2);
  CHECK(c.only_a == 1);
  CHECK(c.only_b == 1);
  CHECK(c.first_differences == std::vector<size_t>{2, 5});
  CHECK_THROWS(rtk::compare_occlusion_arrays(a, std::vector<uint8_t>(3)));
}
