// Chapter 5: exact clipping of a triangle to a box, against analytic answers and against a
// dense sampling of the triangle.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "05_spatial/clip.h"

namespace {

using namespace rtk;

bool same(const Box3f& a, const Box3f& b, float eps = 1e-6f) {
  for (int k = 0; k < 3; ++k)
    if (std::fabs(a.lower[k] - b.lower[k]) > eps || std::fabs(a.upper[k] - b.upper[k]) > eps) return false;
  return true;
}

/// A random triangle and a random box, every coordinate in [-1, 2).
struct TriangleAndBox {
  Vec3f a, b, c;
  Box3f box;
};
TriangleAndBox random_triangle_and_box(std::mt19937& gen) {
  std::uniform_real_distribution<float> u(-1.0f, 2.0f);
  TriangleAndBox t;
  t.a = {u(gen), u(gen), u(gen)};
  t.b = {u(gen), u(gen), u(gen)};
  t.c = {u(gen), u(gen), u(gen)};
  t.box = Box3f(Vec3f{u(gen), u(gen), u(gen)});
  t.box.extend(Vec3f{u(gen), u(gen), u(gen)});
  return t;
}

}  // namespace

TEST_CASE("ch05: a triangle inside the box keeps its own bounds") {
  const Vec3f a{0.1f, 0.2f, 0.3f}, b{0.9f, 0.25f, 0.5f}, c{0.4f, 0.8f, 0.35f};
  const Box3f box({0, 0, 0}, {1, 1, 1});
  CHECK(clip_triangle(a, b, c, box) == Box3f(a).extend(b).extend(c));
}

TEST_CASE("ch05: clipping a right triangle to boxes gives the analytic bounds") {
  // The triangle x + y <= 2, x, y >= 0 in the plane z = 0.
  const Vec3f a{0, 0, 0}, b{2, 0, 0}, c{0, 2, 0};
  // The unit square lies wholly inside the triangle: the box's own square.
  CHECK(same(clip_triangle(a, b, c, Box3f({0, 0, -1}, {1, 1, 1})), Box3f({0, 0, 0}, {1, 1, 0})));
  // x >= 1.5: the corner (1.5, 0) - (2, 0) - (1.5, 0.5).
  CHECK(same(clip_triangle(a, b, c, Box3f({1.5f, -1, -1}, {3, 3, 1})), Box3f({1.5f, 0, 0}, {2, 0.5f, 0})));
  // x, y >= 1.2 lies beyond the hypotenuse: nothing.
  CHECK(clip_triangle(a, b, c, Box3f({1.2f, 1.2f, -1}, {3, 3, 1})).empty());
  // A box beside the plane z = 0: nothing.
  CHECK(clip_triangle(a, b, c, Box3f({0, 0, 0.5f}, {1, 1, 1})).empty());
  // A box whose face is the triangle's plane keeps the part inside it, flat.
  CHECK(same(clip_triangle(a, b, c, Box3f({0, 0, 0}, {0.5f, 3, 1})), Box3f({0, 0, 0}, {0.5f, 2, 0})));
}

TEST_CASE("ch05: a long diagonal triangle clipped to a slab is much tighter than its box") {
  // p(s, t) = (4(s+t), 4s + 4.5t, 4(s+t)): in the slab 1 <= x <= 2, s + t lies in [0.25, 0.5],
  // z = x, and y runs from x to x + t / 2 <= 2.25.
  const Vec3f a{0, 0, 0}, b{4, 4, 4}, c{4, 4.5f, 4};
  const Box3f slab({1, -10, -10}, {2, 10, 10});
  CHECK(same(clip_triangle(a, b, c, slab), Box3f({1, 1, 1}, {2, 2.25f, 2}), 1e-5f));
  const auto [below, above] = split_triangle_box(a, b, c, Box3f(a).extend(b).extend(c), 0, 1.0f);
  CHECK(same(below, Box3f({0, 0, 0}, {1, 1.125f, 1}), 1e-5f));
  CHECK(same(above, Box3f({1, 1, 1}, {4, 4.5f, 4}), 1e-5f));
}

TEST_CASE("ch05: degenerate triangles and boxes") {
  // A segment (zero area) clips like a segment.
  CHECK(same(clip_triangle({0, 0, 0}, {2, 2, 0}, {1, 1, 0}, Box3f({0, 0, -1}, {1, 1, 1})),
             Box3f({0, 0, 0}, {1, 1, 0})));
  // A point inside, and one outside.
  CHECK(clip_triangle({0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, Box3f({0, 0, 0}, {1, 1, 1})) ==
        Box3f(Vec3f(0.5f)));
  CHECK(clip_triangle({2, 2, 2}, {2, 2, 2}, {2, 2, 2}, Box3f({0, 0, 0}, {1, 1, 1})).empty());
  // Non-finite vertices or boxes, and empty boxes, give nothing.
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  CHECK(clip_triangle({nan, 0, 0}, {1, 0, 0}, {0, 1, 0}, Box3f({0, 0, 0}, {1, 1, 1})).empty());
  CHECK(clip_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, Box3f({0, 0, 0}, {inf, 1, 1})).empty());
  CHECK(clip_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, Box3f()).empty());
}

TEST_CASE("ch05: huge coordinates clip without overflow") {
  // Edges of length 6e38 overflow in float; the clipping runs in double.
  const Vec3f a{-3e38f, 0, 0}, b{3e38f, 0, 0}, c{0, 3e38f, 0};
  const Box3f r = clip_triangle(a, b, c, Box3f({-1, -1, -1}, {1, 1, 1}));
  CHECK(same(r, Box3f({-1, 0, 0}, {1, 1, 0})));
  const Box3f far = clip_triangle(a, b, c, Box3f({-3e38f, 0, -1}, {3e38f, 3e38f, 1}));
  CHECK(far == Box3f(a).extend(b).extend(c));
}

TEST_CASE("ch05: clipped bounds contain every sampled point of the triangle in the box, tightly") {
  std::mt19937 gen(501);
  int nonempty = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto [a, b, c, box] = random_triangle_and_box(gen);
    const Box3f r = clip_triangle(a, b, c, box);
    CHECK((r.empty() || box.contains(r)));
    CHECK((r.empty() || (Box3f(a).extend(b).extend(c)).contains(r)));
    // Sample the triangle densely; the sampled points in the box must lie in r, and r must not
    // reach further than a sample spacing beyond them.
    const int n = 60;
    Box3f sampled;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const double s = double(i) / n, t = double(j) / n;
        const Vec3f p{float(a.x + s * (b.x - a.x) + t * (c.x - a.x)), float(a.y + s * (b.y - a.y) + t * (c.y - a.y)),
                      float(a.z + s * (b.z - a.z) + t * (c.z - a.z))};
        if (box.contains(p)) sampled.extend(p);
      }
    if (sampled.empty()) continue;
    ++nonempty;
    REQUIRE(!r.empty());
    const float spacing = 3.0f * 3.0f * 2.0f / float(n);  // longest edge / n, generously
    for (int k = 0; k < 3; ++k) {
      CHECK(r.lower[k] <= sampled.lower[k] + 1e-6f);
      CHECK(r.upper[k] >= sampled.upper[k] - 1e-6f);
      CHECK(r.lower[k] >= sampled.lower[k] - spacing);
      CHECK(r.upper[k] <= sampled.upper[k] + spacing);
    }
  }
  CHECK(nonempty > 50);
}

TEST_CASE("ch05: a triangle or box that is not finite leaves nothing to chop") {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const std::vector<float> planes{0.25f, 0.5f};
  const Box3f box({0, 0, 0}, {1, 1, 1});
  for (const ClippedTriangle& part : {ClippedTriangle({nan, 0, 0}, {1, 0, 0}, {0, 1, 0}, box),
                                      ClippedTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, Box3f({0, 0, 0}, {inf, 1, 1})),
                                      ClippedTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, Box3f())})
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<ExactBox> out(planes.size() + 1);
      part.chop(axis, planes, out);
      for (const ExactBox& piece : out) CHECK(piece.rounded().empty());
    }
}

// [ch05-test-chop]
TEST_CASE("ch05: chopping at many planes gives each slab the bounds of clipping to that slab") {
  std::mt19937 gen(503);
  std::uniform_real_distribution<float> u(-1.0f, 2.0f);
  int pieces = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const auto [a, b, c, box] = random_triangle_and_box(gen);
    // Clipped to the box once, chopped along each axis in turn, as a spatial bin chops it.
    const ClippedTriangle part(a, b, c, box);
    for (int axis = 0; axis < 3; ++axis) {
      // Up to eight sorted planes across the box (some may fall outside the triangle).
      std::vector<float> planes(size_t(1 + (trial + axis) % 8));
      for (float& p : planes) p = box.lower[axis] + (box.upper[axis] - box.lower[axis]) * (u(gen) + 1.0f) / 3.0f;
      std::sort(planes.begin(), planes.end());
      std::vector<ExactBox> out(planes.size() + 1);
      part.chop(axis, planes, out);
      for (size_t i = 0; i < out.size(); ++i) {
        Box3f slab = box;
        if (i > 0) slab.lower[axis] = planes[i - 1];
        if (i < planes.size()) slab.upper[axis] = planes[i];
        const Box3f expected = clip_triangle(a, b, c, slab), chopped = out[i].rounded();
        CHECK(chopped.empty() == expected.empty());
        if (!expected.empty()) {
          ++pieces;
          CHECK(same(chopped, expected));
          CHECK(slab.contains(chopped));
        }
      }
    }
  }
  CHECK(pieces > 600);
}
// [ch05-test-chop]

TEST_CASE("ch05: rounding a union of exact boxes is the union of their roundings") {
  // What lets a spatial bin round once for all its pieces: rounding outwards is monotone, so it
  // commutes with the minimum and maximum of a union and with keeping a box inside a float box.
  std::mt19937 gen(505);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::uniform_int_distribution<int> count(1, 6);
  for (int trial = 0; trial < 500; ++trial) {
    const Box3f keep(Vec3f(float(u(gen)) - 3.0f), Vec3f(float(u(gen)) + 3.0f));
    ExactBox all;
    Box3f each;
    for (int piece = count(gen); piece > 0; --piece) {
      ExactBox b;
      b.extend(std::array<double, 3>{u(gen), u(gen), u(gen)});
      b.extend(std::array<double, 3>{u(gen) * 1e-30, u(gen), -0.0});  // tiny values, a negative zero
      b.clamp_to(keep);
      all.extend(b);
      each.extend(b.rounded());
    }
    const Box3f once = all.rounded();
    CHECK(std::memcmp(&once, &each, sizeof(Box3f)) == 0);
  }
}

TEST_CASE("ch05: extend_clamped is clamp_to and then extend, bit for bit") {
  // chop() adds each piece to its slab's bin in one pass over the axes; the two steps it
  // replaces are the definition. Pieces that cross the box, lie outside it on one axis, or are
  // empty (ExactBox's initial value).
  std::mt19937 gen(707);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 1000; ++trial) {
    const Box3f keep(Vec3f(float(u(gen)) - 1.0f), Vec3f(float(u(gen)) + 1.0f));
    ExactBox piece;
    if (trial % 10 != 0) {
      piece.extend(std::array<double, 3>{u(gen), u(gen), u(gen)});
      piece.extend(std::array<double, 3>{u(gen), u(gen), -0.0});
    }
    ExactBox bin;
    if (trial % 3 != 0) bin.extend(std::array<double, 3>{u(gen), u(gen), u(gen)});
    ExactBox expected = bin, clamped = piece;
    clamped.clamp_to(keep);
    expected.extend(clamped);
    bin.extend_clamped(piece, keep);
    CHECK(std::memcmp(&bin, &expected, sizeof(ExactBox)) == 0);
  }
}
