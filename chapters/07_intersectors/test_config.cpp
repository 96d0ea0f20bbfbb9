// Chapter 7: the `-tri` strings, a layout of chapter 6 with an intersector.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "07_intersectors/triangle_config.h"

using namespace rtk;

TEST_CASE("ch07: every supported configuration parses back from its name") {
  const auto configs = supported_triangle_configs();
  CHECK(configs.size() == 3 + 4 * 3);  // triangle1/4/8 Möller only, the others all three
  for (const TriangleConfig& c : configs) CHECK(parse_triangle_config(c.name()) == c);
}

TEST_CASE("ch07: .fast, .accurate and a bare layout") {
  using L = TriangleLayout;
  using I = IntersectorKind;
  CHECK(parse_triangle_config("triangle4") == TriangleConfig{L::triangle4, I::moeller});
  CHECK(parse_triangle_config("triangle4v.fast") == TriangleConfig{L::triangle4v, I::moeller});
  CHECK(parse_triangle_config("triangle4v.accurate") == TriangleConfig{L::triangle4v, I::watertight});
  CHECK(parse_triangle_config("triangle8.accurate") == TriangleConfig{L::triangle8, I::moeller});
  CHECK(parse_triangle_config("triangle4i.pluecker") == TriangleConfig{L::triangle4i, I::pluecker});
}

TEST_CASE("ch07: unsupported strings are refused with the list of supported ones") {
  for (const char* bad : {"triangle4.pluecker", "triangle1.watertight", "triangle16", "triangle4v.exact",
                          "", ".moeller", "triangle4v.", "Triangle4"}) {
    CAPTURE(bad);
    CHECK_THROWS_WITH_AS(parse_triangle_config(bad), doctest::Contains("triangle4v.pluecker"),
                         std::invalid_argument);
  }
  CHECK_THROWS_WITH_AS(parse_triangle_config("triangle4.pluecker"), doctest::Contains("Möller-Trumbore"),
                       std::invalid_argument);
}
