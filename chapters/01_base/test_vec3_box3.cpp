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
