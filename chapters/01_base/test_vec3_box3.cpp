#include <doctest/doctest.h>

#include <limits>

#include "01_base/box3.h"
#include "01_base/ray.h"

using namespace rtk;

TEST_CASE("ch01: vector algebra") {
  const Vec3f a{1, 2, 3}, b{-4, 5, 0.5f};
  CHECK(dot(a, b) == doctest::Approx(1 * -4 + 2 * 5 + 3 * 0.5));
  const Vec3f c = cross(a, b);
  CHECK(dot(c, a) == doctest::Approx(0.0));
  CHECK(dot(c, b) == doctest::Approx(0.0));
  CHECK(length(normalize(b)) == doctest::Approx(1.0));
  CHECK(max_axis(Vec3f{1, 7, 3}) == 1);
}

TEST_CASE("ch01: min and max follow the SIMD rule with NaN") {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // The second argument wins whenever the comparison is false.
  CHECK(min(Vec3f{nan, 1, 2}, Vec3f{5, 5, 5}).x == 5);
  CHECK(std::isnan(min(Vec3f{5, 1, 2}, Vec3f{nan, 5, 5}).x));
}

TEST_CASE("ch01: boxes grow from empty and measure their surface") {
  Box3f box;
  CHECK(box.empty());
  CHECK(box.half_area() == 0.0f);
  box.extend(Vec3f{0, 0, 0}).extend(Vec3f{1, 2, 3});
  CHECK_FALSE(box.empty());
  CHECK(box.half_area() == doctest::Approx(1 * 2 + 2 * 3 + 3 * 1));
  CHECK(box.contains(Vec3f{0.5f, 1, 2}));
  CHECK_FALSE(box.contains(Vec3f{0.5f, 1, 4}));
  CHECK(box.contains(Box3f{}));  // the empty box is inside everything
  CHECK(intersection(box, Box3f{Vec3f{2}, Vec3f{3}}).empty());
}

TEST_CASE("ch01: rays that are not rays") {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Ray ok;
  ok.dir = {0, 0, 1};
  CHECK(is_valid(ok));  // tfar = +inf is an ordinary ray
  Ray r = ok;
  r.org.y = nan;
  CHECK_FALSE(is_valid(r));
  r = ok;
  r.dir.x = inf;
  CHECK_FALSE(is_valid(r));
  r = ok;
  r.dir = {0, 0, 0};
  CHECK_FALSE(is_valid(r));
  r = ok;
  r.dir = {0, -0.0f, 0};
  CHECK_FALSE(is_valid(r));
  r = ok;
  r.tnear = 2, r.tfar = 1;
  CHECK_FALSE(is_valid(r));
  r = ok;
  r.tfar = nan;
  CHECK_FALSE(is_valid(r));
}

TEST_CASE("ch01: every field of a ray, and each value that can make it no ray") {
  // Each of the eight fields in turn takes each special value; the rules of is_valid say what
  // must come out: org and dir finite, dir not zero, tnear <= tfar with neither NaN; time is
  // not is_valid's business (chapter 8 checks it).
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float tiny = std::numeric_limits<float>::denorm_min();
  const float values[] = {nan, -nan, inf, -inf, 0.0f, -0.0f, tiny, 1.0f, -3.0e38f};
  Ray base;
  base.org = {1, 2, 3}, base.dir = {0.5f, -0.25f, 1}, base.tnear = 0.5f, base.tfar = 10.0f;
  base.time = 0.5f;
  REQUIRE(is_valid(base));
  for (int field = 0; field < 9; ++field)
    for (float value : values) {
      Ray r = base;
      float* slots[] = {&r.org.x, &r.org.y, &r.org.z, &r.tnear, &r.dir.x, &r.dir.y, &r.dir.z, &r.time, &r.tfar};
      *slots[field] = value;
      bool expected = true;
      if (field < 3 || (field >= 4 && field < 7)) expected = std::isfinite(value);
      if (field == 3) expected = !std::isnan(value) && value <= base.tfar;
      if (field == 8) expected = !std::isnan(value) && base.tnear <= value;
      INFO("field ", field, " value ", value);
      CHECK(is_valid(r) == expected);
    }
  // A direction is zero only when all three components are, of either sign.
  for (int signs = 0; signs < 8; ++signs) {
    Ray r = base;
    r.dir = {signs & 1 ? -0.0f : 0.0f, signs & 2 ? -0.0f : 0.0f, signs & 4 ? -0.0f : 0.0f};
    CHECK_FALSE(is_valid(r));
    r.dir.y = tiny;
    CHECK(is_valid(r));
  }
}
