/// \file
/// A two-component vector: sample points in the unit square, film positions, texture
/// coordinates.
#pragma once

namespace rtk {

/// A point in the plane: a 2D sample, a film position or a texture coordinate.
struct Vec2f {
  float x = 0, y = 0;

  constexpr Vec2f() = default;
  constexpr Vec2f(float x_, float y_) : x(x_), y(y_) {}

  constexpr float operator[](int i) const { return i == 0 ? x : y; }
  constexpr bool operator==(const Vec2f&) const = default;
};

constexpr Vec2f operator+(Vec2f a, Vec2f b) { return {a.x + b.x, a.y + b.y}; }
constexpr Vec2f operator-(Vec2f a, Vec2f b) { return {a.x - b.x, a.y - b.y}; }
constexpr Vec2f operator*(Vec2f a, Vec2f b) { return {a.x * b.x, a.y * b.y}; }
constexpr Vec2f operator*(Vec2f a, float s) { return {a.x * s, a.y * s}; }
constexpr Vec2f operator*(float s, Vec2f a) { return {a.x * s, a.y * s}; }

}  // namespace rtk
