#include "05_spatial/clip.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>
#include <type_traits>

#include "01_base/platform.h"

namespace rtk {

namespace {

using Polygon = ClipPolygon;  // clip.h's, by a short name

/// A side of a cut that is not wanted.
constexpr Polygon* kNoSide = nullptr;

// [ch05-clip-plane]
/// What a side of a cut keeps of a point: a polygon the point itself, an exact box only its
/// bounds (a piece that no later plane cuts needs nothing more).
void add(Polygon& poly, const std::array<double, 3>& p) { poly.v[poly.n++] = p; }
void add(ExactBox& box, const std::array<double, 3>& p) { box.extend(p); }

/// Cuts `in` at the plane coordinate[axis] = d: the part below it goes to `below`, the part
/// above it to `above` (either may be null when only one side is wanted; a polygon given is
/// emptied first, a box is extended). A vertex on the plane belongs to both. Where an edge
/// crosses, the new vertex gets the plane's coordinate exactly, and the other two are
/// interpolated from the edge's endpoints taken in a fixed order (lower coordinate first), so
/// that two neighbouring clips of one edge compute the same point bit for bit; a point both
/// sides need is computed once.
template <class Below, class Above>
void split_plane(const Polygon& in, int axis, double d, Below* below, Above* above) {
  if constexpr (std::is_same_v<Below, Polygon>)
    if (below) below->n = 0;
  if constexpr (std::is_same_v<Above, Polygon>)
    if (above) above->n = 0;
  for (int i = 0; i < in.n; ++i) {
    const auto& p = in.v[i];
    const auto& q = in.v[(i + 1) % in.n];
    const bool p_below = p[axis] <= d, q_below = q[axis] <= d;
    const bool p_above = p[axis] >= d, q_above = q[axis] >= d;
    if (below && p_below) add(*below, p);
    if (above && p_above) add(*above, p);
    const bool cross_below = below && p_below != q_below, cross_above = above && p_above != q_above;
    if (cross_below || cross_above) {
      const auto& s = p[axis] < q[axis] ? p : q;
      const auto& e = p[axis] < q[axis] ? q : p;
      const double t = (d - s[axis]) / (e[axis] - s[axis]);
      // Each coordinate in a register of its own: a point written coordinate by coordinate
      // and then copied whole would be read back before the processor can forward the stores.
      auto at = [&](int k) { return k == axis ? d : s[k] + t * (e[k] - s[k]); };
      const std::array<double, 3> x{at(0), at(1), at(2)};
      if (cross_below) add(*below, x);
      if (cross_above) add(*above, x);
    }
  }
}
// [ch05-clip-plane]

/// The largest float not above `d`, and the smallest not below it (d finite and within float
/// range: the clipped points lie between the triangle's float vertices). The nearest float is
/// above `d` about half the time, at random, so the step down is computed always and chosen
/// by a select rather than a branch that would be mispredicted that often: one float step on
/// the bits (down for a positive float, up for a negative one, from zero to the smallest
/// negative float), without a libm call.
float round_down(double d) {
  const float f = float(d);
  const uint32_t bits = std::bit_cast<uint32_t>(f), sign = bits >> 31;
  const uint32_t step = select_bits((bits & 0x7fffffffu) == 0, bits - 1 + 2 * sign, 0x80000001u);
  return std::bit_cast<float>(select_bits(double(f) > d, bits, step));
}
float round_up(double d) { return -round_down(-d); }

bool finite(const Vec3f& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

/// The polygon's exact bounds.
ExactBox exact_bounds(const Polygon& poly) {
  ExactBox b;
  for (int i = 0; i < poly.n; ++i) b.extend(poly.v[i]);
  return b;
}

/// The polygon's exact bounds, kept inside `box`.
ExactBox exact_bounds_in(const Polygon& poly, const Box3f& box) {
  ExactBox b = exact_bounds(poly);
  b.clamp_to(box);
  return b;
}

/// The polygon's bounds, rounded outwards to floats and kept inside `box`.
Box3f bounds_in(const Polygon& poly, const Box3f& box) { return exact_bounds_in(poly, box).rounded(); }

bool usable(const Vec3f& a, const Vec3f& b, const Vec3f& c, const Box3f& box) {
  return !box.empty() && finite(a) && finite(b) && finite(c) && finite(box.lower) && finite(box.upper);
}

/// The triangle clipped to the box, as a polygon. A box that holds the whole triangle (a
/// reference no split has cut yet) costs no clipping at all.
Polygon clip_to_box(const Vec3f& a, const Vec3f& b, const Vec3f& c, const Box3f& box) {
  Polygon poly;
  for (const Vec3f& p : {a, b, c}) poly.v[poly.n++] = {double(p.x), double(p.y), double(p.z)};
  if (box.contains(a) && box.contains(b) && box.contains(c)) return poly;
  Polygon above_lower;
  for (int axis = 0; axis < 3 && poly.n > 0; ++axis) {
    split_plane(poly, axis, double(box.lower[axis]), kNoSide, &above_lower);
    split_plane(above_lower, axis, double(box.upper[axis]), &poly, kNoSide);
  }
  return poly;
}

}  // namespace

Box3f ExactBox::rounded() const {
  // (+ 0.0f turns a negative zero into a positive one, as chapter 4's builder expects.) The
  // corners are made whole, not written axis by axis, for the reason given in split_plane().
  auto low = [&](int k) { return round_down(lower[k]) + 0.0f; };
  auto high = [&](int k) { return round_up(upper[k]) + 0.0f; };
  return {Vec3f(low(0), low(1), low(2)), Vec3f(high(0), high(1), high(2))};
}

ClippedTriangle::ClippedTriangle(const Vec3f& a, const Vec3f& b, const Vec3f& c, const Box3f& box)
    : part_(usable(a, b, c, box) ? clip_to_box(a, b, c, box) : Polygon{}), box_(box) {}

void ClippedTriangle::chop(int axis, std::span<const float> planes, std::span<ExactBox> out) const {
  if (out.size() != planes.size() + 1) return;
  // What is left above the planes cut so far: the clipped part, then two polygons in turn.
  // Each piece below a plane is kept as its bounds alone.
  std::array<Polygon, 2> rest;
  const Polygon* left = &part_;
  Box3f slab = box_;
  for (size_t i = 0; i < planes.size() && left->n > 0; ++i) {
    const float p = std::clamp(planes[i], box_.lower[axis], box_.upper[axis]);
    slab.upper[axis] = p;
    ExactBox piece;
    split_plane(*left, axis, double(p), &piece, &rest[i % 2]);
    out[i].extend_clamped(piece, slab);
    left = &rest[i % 2];
    slab.lower[axis] = p;
  }
  slab.upper[axis] = box_.upper[axis];
  out[planes.size()].extend_clamped(exact_bounds(*left), slab);
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
  Polygon part_below, part_above;
  split_plane(clip_to_box(a, b, c, box), axis, double(pos), &part_below, &part_above);
  return {bounds_in(part_below, below), bounds_in(part_above, above)};
}

}  // namespace rtk
