/// \file
/// Exact clipping of a triangle to a box: the tight bounds of the part of a triangle that lies
/// inside a box, which is what a reference made by a spatial split stands for (Stich, Friedrich
/// and Dietrich, "Spatial Splits in Bounding Volume Hierarchies", HPG 2009, section 4.2).
#pragma once

#include <array>
#include <limits>
#include <span>
#include <utility>

#include "01_base/box3.h"

namespace rtk {

// [ch05-exact-box]
/// A box in double precision, grown by the exact points of clipped polygons and rounded to
/// floats only when a float box is wanted. rounded() rounds each bound outwards, and rounding
/// outwards is monotone: the rounding of a union (or of a box kept inside a float box) is the
/// union of the roundings (the same box kept inside it). So a spatial bin can gather the
/// exact bounds of every piece chopped into it and round once, with the bits that rounding
/// each piece would give.
struct ExactBox {
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  std::array<double, 3> lower{kInf, kInf, kInf}, upper{-kInf, -kInf, -kInf};

  void extend(const std::array<double, 3>& p) {
    for (int k = 0; k < 3; ++k) {
      lower[k] = p[k] < lower[k] ? p[k] : lower[k];
      upper[k] = p[k] > upper[k] ? p[k] : upper[k];
    }
  }
  void extend(const ExactBox& b) {
    for (int k = 0; k < 3; ++k) {
      lower[k] = b.lower[k] < lower[k] ? b.lower[k] : lower[k];
      upper[k] = b.upper[k] > upper[k] ? b.upper[k] : upper[k];
    }
  }
  void extend(const Box3f& b) {
    extend(ExactBox{{double(b.lower.x), double(b.lower.y), double(b.lower.z)},
                    {double(b.upper.x), double(b.upper.y), double(b.upper.z)}});
  }
  /// Keeps the box inside `box`.
  void clamp_to(const Box3f& box) {
    for (int k = 0; k < 3; ++k) {
      lower[k] = double(box.lower[k]) > lower[k] ? double(box.lower[k]) : lower[k];
      upper[k] = double(box.upper[k]) < upper[k] ? double(box.upper[k]) : upper[k];
    }
  }
  /// Extends the box by `piece` kept inside `box`: piece.clamp_to(box), then extend(piece), in
  /// one pass over the axes. (Done in two, the clamped piece's lower corner was written one
  /// coordinate at a time and read back two at a time, which a processor cannot forward from
  /// its store buffer: the hottest instruction of a spatial build's chop.)
  void extend_clamped(const ExactBox& piece, const Box3f& box) {
    for (int k = 0; k < 3; ++k) {
      const double keep_lower = double(box.lower[k]), keep_upper = double(box.upper[k]);
      const double lo = keep_lower > piece.lower[k] ? keep_lower : piece.lower[k];
      const double hi = keep_upper < piece.upper[k] ? keep_upper : piece.upper[k];
      lower[k] = lo < lower[k] ? lo : lower[k];
      upper[k] = hi > upper[k] ? hi : upper[k];
    }
  }
  /// The smallest float box that contains this one (an empty box stays empty).
  Box3f rounded() const;
};
// [ch05-exact-box]

/// The bounds of the part of triangle (a, b, c) inside `box` (closed): the triangle is clipped as
/// a polygon against the box's six planes (Sutherland and Hodgman, "Reentrant polygon
/// clipping", CACM 1974) in double precision, and the result rounded outwards to floats and
/// kept inside `box`, so that it contains the clipped part and never leaves the box. Returns an
/// empty box when the triangle misses the box, or when a vertex or the box is not finite.
/// Zero-area triangles (segments, points) are clipped like any other polygon.
Box3f clip_triangle(const Vec3f& a, const Vec3f& b, const Vec3f& c, const Box3f& box);

/// Splits a reference to triangle (a, b, c) whose current box is `box` by the plane
/// coordinate[axis] = pos: the bounds of the triangle's part in `box` below the plane and above
/// it (either may be empty when the triangle only touches that side).
std::pair<Box3f, Box3f> split_triangle_box(const Vec3f& a, const Vec3f& b, const Vec3f& c,
                                           const Box3f& box, int axis, float pos);

/// A polygon during clipping: a triangle clipped by six planes has at most nine vertices (each
/// plane adds at most one).
struct ClipPolygon {
  static constexpr int kMaxVertices = 10;
  std::array<std::array<double, 3>, kMaxVertices> v;
  int n = 0;
};

/// The part of triangle (a, b, c) inside a reference's box, clipped once, and chopped along
/// each axis a spatial bin asks for (SBVH's reference chopping, done incrementally: each plane
/// splits off one piece of what is left). A triangle or box that is not finite, or a box that
/// is empty, leaves nothing to chop.
class ClippedTriangle {
 public:
  ClippedTriangle(const Vec3f& a, const Vec3f& b, const Vec3f& c, const Box3f& box);

  /// Chops the part at the planes coordinate[axis] = planes[0] < planes[1] < ..., and extends
  /// out[i] by the bounds of the piece between planes[i - 1] and planes[i] (out holds
  /// planes.size() + 1 boxes; the first and last pieces end at the box). Each piece's bounds
  /// are exact and kept in their slab; out[i].rounded() is what clip_triangle() gives for that
  /// slab, bit for bit.
  void chop(int axis, std::span<const float> planes, std::span<ExactBox> out) const;

 private:
  ClipPolygon part_;  // empty when there is nothing to chop
  Box3f box_;
};

}  // namespace rtk
