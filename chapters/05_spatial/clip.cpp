#include "05_spatial/clip.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>

namespace rtk {

namespace {

/// A polygon during clipping: a triangle clipped by six planes has at most nine vertices (each
/// plane adds at most one).
struct Polygon {
  static constexpr int kMaxVertices = 10;
  std::array<std::array<double, 3>, kMaxVertices> v;
  int n = 0;
};

// [ch05-clip-plane]
/// Keeps the part of `in` on one side of the plane coordinate[axis] = d: below it (keep_below)
/// or above it. A vertex on the plane is kept. Where an edge crosses, the new vertex gets the
/// plane's coordinate exactly, and the other two are interpolated from the edge's endpoints
/// taken in a fixed order (lower coordinate first), so that two neighbouring clips of one edge
/// compute the same point bit for bit.
Polygon clip_plane(const Polygon& in, int axis, double d, bool keep_below) {
  Polygon out;
  auto inside = [&](const std::array<double, 3>& p) { return keep_below ? p[axis] <= d : p[axis] >= d; };
  for (int i = 0; i < in.n; ++i) {
    const auto& p = in.v[i];
    const auto& q = in.v[(i + 1) % in.n];
    const bool p_in = inside(p), q_in = inside(q);
    if (p_in) out.v[out.n++] = p;
    if (p_in != q_in) {
      const auto& s = p[axis] < q[axis] ? p : q;
      const auto& e = p[axis] < q[axis] ? q : p;
      const double t = (d - s[axis]) / (e[axis] - s[axis]);
      std::array<double, 3> x;
      for (int k = 0; k < 3; ++k) x[k] = s[k] + t * (e[k] - s[k]);
      x[axis] = d;
      out.v[out.n++] = x;
    }
  }
  return out;
}
// [ch05-clip-plane]

/// The largest float not above `d`, and the smallest not below it (d finite and within float
/// range: the clipped points lie between the triangle's float vertices). One float step is
/// taken on the bits, without a libm call.
float round_down(double d) {
  const float f = float(d);
  if (double(f) <= d) return f;
  const uint32_t bits = std::bit_cast<uint32_t>(f);
  if (f > 0.0f) return std::bit_cast<float>(bits - 1);
  if (f == 0.0f) return -std::numeric_limits<float>::denorm_min();
  return std::bit_cast<float>(bits + 1);
}
float round_up(double d) { return -round_down(-d); }

bool finite(const Vec3f& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

/// The polygon's bounds, rounded outwards to floats and kept inside `box`.
Box3f bounds_in(const Polygon& poly, const Box3f& box) {
  if (poly.n == 0) return {};
  Box3f out;
  std::array<double, 3> low = poly.v[0], high = poly.v[0];
  for (int i = 1; i < poly.n; ++i)
    for (int axis = 0; axis < 3; ++axis) {
      const double x = poly.v[i][axis];
      low[axis] = x < low[axis] ? x : low[axis];
      high[axis] = x > high[axis] ? x : high[axis];
    }
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = low[axis], hi = high[axis];
    // (+ 0.0f turns a negative zero into a positive one, as chapter 4's builder expects.)
    out.lower[axis] = std::max(round_down(lo), box.lower[axis]) + 0.0f;
    out.upper[axis] = std::min(round_up(hi), box.upper[axis]) + 0.0f;
  }
  return out;
}

bool usable(const Vec3f& a, const Vec3f& b, const Vec3f& c, const Box3f& box) {
  return !box.empty() && finite(a) && finite(b) && finite(c) && finite(box.lower) && finite(box.upper);
}

/// The triangle clipped to the box, as a polygon. A box that holds the whole triangle (a
/// reference no split has cut yet) costs no clipping at all.
Polygon clip_to_box(const Vec3f& a, const Vec3f& b, const Vec3f& c, const Box3f& box) {
  Polygon poly;
  for (const Vec3f& p : {a, b, c}) poly.v[poly.n++] = {double(p.x), double(p.y), double(p.z)};
  if (box.contains(a) && box.contains(b) && box.contains(c)) return poly;
  for (int axis = 0; axis < 3 && poly.n > 0; ++axis) {
    poly = clip_plane(poly, axis, double(box.lower[axis]), false);
    if (poly.n > 0) poly = clip_plane(poly, axis, double(box.upper[axis]), true);
  }
  return poly;
}

}  // namespace

void chop_triangle(const Vec3f& a, const Vec3f& b, const Vec3f& c, const Box3f& box, int axis,
                   std::span<const float> planes, std::span<Box3f> out) {
  if (!usable(a, b, c, box) || out.size() != planes.size() + 1) return;
  Polygon rest = clip_to_box(a, b, c, box);
  Box3f slab = box;
  for (size_t i = 0; i < planes.size() && rest.n > 0; ++i) {
    const float p = std::clamp(planes[i], box.lower[axis], box.upper[axis]);
    slab.upper[axis] = p;
    out[i].extend(bounds_in(clip_plane(rest, axis, double(p), true), slab));
    rest = clip_plane(rest, axis, double(p), false);
    slab.lower[axis] = p;
  }
  slab.upper[axis] = box.upper[axis];
  out[planes.size()].extend(bounds_in(rest, slab));
}

Box3f clip_triangle(const Vec3f& a, const Vec3f& b, const Vec3f& c, const Box3f& box) {
  if (!usable(a, b, c, box)) return {};
  return bounds_in(clip_to_box(a, b, c, box), box);
}

std::pair<Box3f, Box3f> split_triangle_box(const Vec3f& a, const Vec3f& b, const Vec3f& c,
                                           const Box3f& box, int axis, float pos) {
  if (!usable(a, b, c, box)) return {};
  Box3f below = box, above = box;
  below.upper[axis] = std::min(box.upper[axis], pos);
  above.lower[axis] = std::max(box.lower[axis], pos);
  if (below.empty() || above.empty()) return {clip_triangle(a, b, c, below), clip_triangle(a, b, c, above)};
  // Clip to the box once, then cut the polygon at the plane.
  const Polygon poly = clip_to_box(a, b, c, box);
  return {bounds_in(clip_plane(poly, axis, double(pos), true), below),
          bounds_in(clip_plane(poly, axis, double(pos), false), above)};
}

}  // namespace rtk
