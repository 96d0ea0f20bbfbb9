/// \file
/// Axis-aligned bounding boxes: what every BVH node stores about its children.
#pragma once

#include <limits>

#include "01_base/vec3.h"

namespace rtk {

/// An axis-aligned box; the default box is empty (lower = +inf, upper = -inf), so that
/// extending it by anything gives that thing.
struct Box3f {
  Vec3f lower{std::numeric_limits<float>::infinity()};
  Vec3f upper{-std::numeric_limits<float>::infinity()};

  constexpr Box3f() = default;
  constexpr Box3f(Vec3f lo, Vec3f hi) : lower(lo), upper(hi) {}
  constexpr explicit Box3f(Vec3f p) : lower(p), upper(p) {}

  constexpr bool empty() const { return !(lower.x <= upper.x && lower.y <= upper.y && lower.z <= upper.z); }
  constexpr Box3f& extend(Vec3f p) { lower = min(lower, p); upper = max(upper, p); return *this; }
  constexpr Box3f& extend(const Box3f& b) { lower = min(lower, b.lower); upper = max(upper, b.upper); return *this; }
  constexpr Vec3f size() const { return upper - lower; }
  constexpr Vec3f center() const { return (lower + upper) * 0.5f; }
  /// Twice the centroid: as good as the centroid for comparisons, one multiplication cheaper.
  constexpr Vec3f center2() const { return lower + upper; }
  /// Half the surface area (what the SAH needs, up to a constant); zero for an empty box.
  constexpr float half_area() const {
    if (empty()) return 0.0f;
    const Vec3f d = size();
    return d.x * d.y + d.y * d.z + d.z * d.x;
  }
  constexpr bool contains(Vec3f p) const {
    return lower.x <= p.x && p.x <= upper.x && lower.y <= p.y && p.y <= upper.y &&
           lower.z <= p.z && p.z <= upper.z;
  }
  constexpr bool contains(const Box3f& b) const { return b.empty() || (contains(b.lower) && contains(b.upper)); }
  constexpr bool operator==(const Box3f&) const = default;
};

constexpr Box3f merge(Box3f a, const Box3f& b) { return a.extend(b); }

/// The intersection of two boxes (empty when they do not overlap).
constexpr Box3f intersection(const Box3f& a, const Box3f& b) {
  return {max(a.lower, b.lower), min(a.upper, b.upper)};
}

}  // namespace rtk
