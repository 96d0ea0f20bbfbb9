/// \file
/// Point and directional lights: delta lights, reached by one direction each.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "11_sampling/warp.h"
#include "13_lights/light.h"

namespace rtk {

namespace detail {
/// Throws std::invalid_argument unless every component is finite and non-negative.
inline Color checked_radiance(Color c, const char* what) {
  if (!is_finite(c) || c.r < 0 || c.g < 0 || c.b < 0)
    throw std::invalid_argument(std::string(what) + " must be finite and >= 0");
  return c;
}
/// Throws std::invalid_argument unless the vector is finite and non-zero; returns it normalised.
inline Vec3f checked_direction(Vec3f d, const char* what) {
  if (!is_finite(d) || (d.x == 0 && d.y == 0 && d.z == 0))
    throw std::invalid_argument(std::string(what) + " must be a finite, non-zero vector");
  return normalize(d);
}
}  // namespace detail

// [ch13-point]
/// An isotropic point light of intensity I (the guide's -pointlight px py pz r g b): it
/// delivers I / d^2 to a point at distance d.
class PointLight final : public Light {
 public:
  /// A point light at `position` with intensity `intensity` (W/sr per channel).
  PointLight(Vec3f position, Color intensity)
      : position_(position),
        intensity_(detail::checked_radiance(intensity, "point light intensity")) {
    if (!is_finite(position)) throw std::invalid_argument("point light position must be finite");
  }
  std::optional<LightSample> sample_li(const LightQuery& q, Vec2f) const override {
    const Vec3f d = position_ - q.p;
    const float d2 = dot(d, d);
    if (!(d2 > 0.0f) || !std::isfinite(d2)) return std::nullopt;
    const float dist = std::sqrt(d2);
    return LightSample{d / dist, intensity_ / d2, 1.0f, dist, true};
  }
  float pdf_li(const LightQuery&, Vec3f) const override { return 0.0f; }
  Color power(float) const override { return intensity_ * (4.0f * kPi); }
  bool is_delta() const override { return true; }

 private:
  Vec3f position_;
  Color intensity_;
};
// [ch13-point]

// [ch13-spot]
/// A point light that shines into a cone (the -spotlight px py pz dx dy dz r g b angleMin
/// angleMax of Embree 2's scripts, Embree 1.1's SpotLight): full intensity I within angleMin
/// degrees of its axis, none beyond angleMax, and between the two a falloff linear in the
/// cosine of the angle, so that the light fades smoothly at the cone's edge. The angles are
/// half-angles, from the axis to the cone's side.
class SpotLight final : public Light {
 public:
  /// A spot at `position` pointing along `direction`, with intensity `intensity` (W/sr) inside
  /// `inner_degrees` and none outside `outer_degrees` (0 <= inner <= outer <= 180).
  SpotLight(Vec3f position, Vec3f direction, Color intensity, float inner_degrees, float outer_degrees)
      : position_(position),
        axis_(detail::checked_direction(direction, "spot light direction")),
        intensity_(detail::checked_radiance(intensity, "spot light intensity")) {
    if (!is_finite(position)) throw std::invalid_argument("spot light position must be finite");
    if (!(inner_degrees >= 0.0f && inner_degrees <= outer_degrees && outer_degrees <= 180.0f))
      throw std::invalid_argument("spot light angles must satisfy 0 <= angleMin <= angleMax <= 180 degrees");
    h_inner_ = one_minus_cos(inner_degrees * kPi / 180.0f);
    h_outer_ = one_minus_cos(outer_degrees * kPi / 180.0f);
  }
  /// The fraction of the intensity emitted along the unit direction `w` (away from the light):
  /// linear in cos(theta) between the cones, here in h = 1 - cos(theta) (chapter 11's
  /// one_minus_cos_between), which keeps its digits for a beam narrower than a float cosine
  /// can tell from 1.
  float falloff(Vec3f w) const {
    const float h = one_minus_cos_between(w, axis_);
    if (h <= h_inner_) return 1.0f;
    if (h >= h_outer_) return 0.0f;
    return (h_outer_ - h) / (h_outer_ - h_inner_);
  }
  std::optional<LightSample> sample_li(const LightQuery& q, Vec2f) const override {
    const Vec3f d = position_ - q.p;
    const float d2 = dot(d, d);
    if (!(d2 > 0.0f) || !std::isfinite(d2)) return std::nullopt;
    const float dist = std::sqrt(d2);
    const float f = falloff(-d / dist);
    if (!(f > 0.0f)) return std::nullopt;
    return LightSample{d / dist, intensity_ * (f / d2), 1.0f, dist, true};
  }
  float pdf_li(const LightQuery&, Vec3f) const override { return 0.0f; }
  /// I times the solid angle the falloff weighs: with c = cos(theta), the integral of the
  /// falloff over the sphere is 2 pi (1 - c_inner + (c_inner - c_outer) / 2), which is
  /// pi (h_inner + h_outer).
  Color power(float) const override { return intensity_ * (kPi * (h_inner_ + h_outer_)); }
  bool is_delta() const override { return true; }

 private:
  Vec3f position_, axis_;
  Color intensity_;
  float h_inner_ = 0.0f, h_outer_ = 0.0f;  // 1 - cos of each cone's half-angle
};
// [ch13-spot]

/// Light from infinitely far away in one direction (the guide's -directionallight dx dy dz
/// r g b): `direction` is the way the light travels, `irradiance` what a surface facing it
/// receives.
class DirectionalLight final : public Light {
 public:
  /// A light travelling along `direction` with irradiance `irradiance`.
  DirectionalLight(Vec3f direction, Color irradiance)
      : wi_(-detail::checked_direction(direction, "directional light direction")),
        irradiance_(detail::checked_radiance(irradiance, "directional light irradiance")) {}
  std::optional<LightSample> sample_li(const LightQuery&, Vec2f) const override {
    return LightSample{wi_, irradiance_, 1.0f, std::numeric_limits<float>::infinity(), true};
  }
  float pdf_li(const LightQuery&, Vec3f) const override { return 0.0f; }
  /// The irradiance through the scene's cross-section.
  Color power(float scene_radius) const override {
    return irradiance_ * (kPi * scene_radius * scene_radius);
  }
  bool is_delta() const override { return true; }
  bool is_infinite() const override { return true; }

 private:
  Vec3f wi_;
  Color irradiance_;
};

}  // namespace rtk
