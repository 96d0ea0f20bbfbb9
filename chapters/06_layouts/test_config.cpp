// Chapter 6: the `-tri` strings and the default layout.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "06_layouts/triangle_config.h"

using namespace rtk;

TEST_CASE("ch06: every supported configuration parses back from its name") {
  const auto configs = supported_triangle_configs();
  CHECK(configs.size() == 3 + 4 * 3);  // triangle1/4/8 Möller only, the others all three
  for (const TriangleConfig& c : configs) CHECK(parse_triangle_config(c.name()) == c);
}

TEST_CASE("ch06: .fast, .accurate and a bare layout") {
  using L = TriangleLayout;
  using I = IntersectorKind;
  CHECK(parse_triangle_config("triangle4") == TriangleConfig{L::triangle4, I::moeller});
  CHECK(parse_triangle_config("triangle4v.fast") == TriangleConfig{L::triangle4v, I::moeller});
  CHECK(parse_triangle_config("triangle4v.accurate") == TriangleConfig{L::triangle4v, I::watertight});
  CHECK(parse_triangle_config("triangle8.accurate") == TriangleConfig{L::triangle8, I::moeller});
  CHECK(parse_triangle_config("triangle4i.pluecker") == TriangleConfig{L::triangle4i, I::pluecker});
}

TEST_CASE("ch06: unsupported strings are refused with the list of supported ones") {
  for (const char* bad : {"triangle4.pluecker", "triangle1.watertight", "triangle16", "triangle4v.exact",
                          "", ".moeller", "triangle4v.", "Triangle4"}) {
    CAPTURE(bad);
    CHECK_THROWS_WITH_AS(parse_triangle_config(bad), doctest::Contains("triangle4v.pluecker"),
                         std::invalid_argument);
  }
  CHECK_THROWS_WITH_AS(parse_triangle_config("triangle4.pluecker"), doctest::Contains("Möller-Trumbore"),
                       std::invalid_argument);
}

// [ch06-test-default]
TEST_CASE("ch06: the default layout follows the ISA, and the memory budget") {
  CHECK(choose_default_layout(1000, Isa::sse4) == TriangleLayout::triangle4);
  CHECK(choose_default_layout(1000, Isa::avx2) == TriangleLayout::triangle8);
  CHECK(choose_default_layout(1000, Isa::avx512) == TriangleLayout::triangle8);
  CHECK(choose_default_layout(1000, Isa::scalar) == TriangleLayout::triangle8);
  // A hundred million triangles in 6 GiB: the fast layout (8.5 GB) would not fit, the lean one
  // (4.5 GB) does.
  const size_t gb = size_t(1) << 30;
  CHECK(choose_default_layout(100'000'000, Isa::avx2, 6 * gb) == TriangleLayout::triangle4i);
  CHECK(choose_default_layout(100'000'000, Isa::avx2, 64 * gb) == TriangleLayout::triangle8);
  // The estimates order the layouts as their blocks do.
  CHECK(estimated_bytes_per_triangle(TriangleLayout::triangle4i) <
        estimated_bytes_per_triangle(TriangleLayout::triangle4));
}
// [ch06-test-default]
