/// \file
/// The renderer's colour: linear RGB radiance, reflectance or weight, three floats.
/// It lives in chapter 1, with the other value types, because the layer beneath the chapters
/// (the framebuffer and image files of lib/image) carries colours as well as the renderer's
/// chapters from 10 on.
#pragma once

#include <cmath>

namespace rtk {

/// A linear RGB triple: radiance, a reflectance, or a path's throughput. Operations are
/// component-wise; there is no clamping anywhere, because a renderer must see an energy
/// gain (a bug) rather than have it hidden.
struct Color {
  float r = 0, g = 0, b = 0;

  constexpr Color() = default;
  constexpr Color(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
  constexpr explicit Color(float s) : r(s), g(s), b(s) {}

  constexpr float operator[](int i) const { return i == 0 ? r : i == 1 ? g : b; }
  constexpr Color& operator+=(Color c) { return *this = {r + c.r, g + c.g, b + c.b}; }
  constexpr Color& operator*=(Color c) { return *this = {r * c.r, g * c.g, b * c.b}; }
  constexpr Color& operator*=(float s) { return *this = {r * s, g * s, b * s}; }
  constexpr bool operator==(const Color&) const = default;
};

static_assert(sizeof(Color) == 12,
              "an array of Colors is an array of RGB floats (image files, textures)");

constexpr Color operator+(Color a, Color b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }
constexpr Color operator-(Color a, Color b) { return {a.r - b.r, a.g - b.g, a.b - b.b}; }
constexpr Color operator*(Color a, Color b) { return {a.r * b.r, a.g * b.g, a.b * b.b}; }
constexpr Color operator/(Color a, Color b) { return {a.r / b.r, a.g / b.g, a.b / b.b}; }
constexpr Color operator*(Color a, float s) { return {a.r * s, a.g * s, a.b * s}; }
constexpr Color operator*(float s, Color a) { return {a.r * s, a.g * s, a.b * s}; }
constexpr Color operator/(Color a, float s) { return {a.r / s, a.g / s, a.b / s}; }

/// Luminance with the Rec. 709 / sRGB primaries' weights: what importance sampling of an
/// environment map and lobe selection use as "how bright".
constexpr float luminance(Color c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }
/// The largest component (Russian roulette and lobe selection want the worst case).
constexpr float max_component(Color c) {
  return c.r > c.g ? (c.r > c.b ? c.r : c.b) : (c.g > c.b ? c.g : c.b);
}
/// The mean of the three components.
constexpr float average(Color c) { return (c.r + c.g + c.b) * (1.0f / 3.0f); }
/// Whether all components are exactly zero.
constexpr bool is_black(Color c) { return c.r == 0.0f && c.g == 0.0f && c.b == 0.0f; }
/// Whether no component is NaN or infinite.
inline bool is_finite(Color c) {
  return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}
/// Component-wise square root, exponential and power (Fresnel and absorption need them).
inline Color sqrt(Color c) { return {std::sqrt(c.r), std::sqrt(c.g), std::sqrt(c.b)}; }
inline Color exp(Color c) { return {std::exp(c.r), std::exp(c.g), std::exp(c.b)}; }
inline Color pow(Color c, float e) {
  return {std::pow(c.r, e), std::pow(c.g, e), std::pow(c.b, e)};
}

}  // namespace rtk
