/// \file
/// The short vector of the base library: three floats, with the operations geometry needs.
#pragma once

#include <cmath>

namespace rtk {

/// A point or direction in 3D, 12 bytes, no padding (it is the layout of the ray files).
struct Vec3f {
  float x = 0, y = 0, z = 0;

  constexpr Vec3f() = default;
  constexpr Vec3f(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
  constexpr explicit Vec3f(float s) : x(s), y(s), z(s) {}

  constexpr float operator[](int axis) const { return axis == 0 ? x : axis == 1 ? y : z; }
  constexpr float& operator[](int axis) { return axis == 0 ? x : axis == 1 ? y : z; }

  constexpr Vec3f operator-() const { return {-x, -y, -z}; }
  constexpr Vec3f& operator+=(Vec3f b) { return *this = {x + b.x, y + b.y, z + b.z}; }
  constexpr Vec3f& operator-=(Vec3f b) { return *this = {x - b.x, y - b.y, z - b.z}; }
  constexpr Vec3f& operator*=(float s) { return *this = {x * s, y * s, z * s}; }
  constexpr bool operator==(const Vec3f&) const = default;
};
static_assert(sizeof(Vec3f) == 12, "Vec3f is stored in files and SoA blocks as three floats");

constexpr Vec3f operator+(Vec3f a, Vec3f b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3f operator-(Vec3f a, Vec3f b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3f operator*(Vec3f a, Vec3f b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
constexpr Vec3f operator*(Vec3f a, float s) { return {a.x * s, a.y * s, a.z * s}; }
constexpr Vec3f operator*(float s, Vec3f a) { return {a.x * s, a.y * s, a.z * s}; }
constexpr Vec3f operator/(Vec3f a, float s) { return {a.x / s, a.y / s, a.z / s}; }

constexpr float dot(Vec3f a, Vec3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3f cross(Vec3f a, Vec3f b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float length(Vec3f a) { return std::sqrt(dot(a, a)); }
inline Vec3f normalize(Vec3f a) { return a * (1.0f / length(a)); }

/// Component-wise minimum and maximum with the SIMD rule `a < b ? a : b`, so that scalar and
/// vector code agree when a NaN is involved (the second argument wins).
constexpr Vec3f min(Vec3f a, Vec3f b) {
  return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z};
}
constexpr Vec3f max(Vec3f a, Vec3f b) {
  return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z};
}
inline Vec3f abs(Vec3f a) { return {std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}; }
constexpr float reduce_max(Vec3f a) { return a.x > a.y ? (a.x > a.z ? a.x : a.z) : (a.y > a.z ? a.y : a.z); }
constexpr float reduce_min(Vec3f a) { return a.x < a.y ? (a.x < a.z ? a.x : a.z) : (a.y < a.z ? a.y : a.z); }
/// The axis (0, 1, 2) of the largest component.
constexpr int max_axis(Vec3f a) { return a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2); }
inline bool is_finite(Vec3f a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

}  // namespace rtk
