/// \file
/// Lights at infinity that are not deltas: a distant disk of directions (a sun with a
/// size) and a uniform ambient sky.
#pragma once

#include <cmath>
#include <stdexcept>

#include "11_sampling/frame.h"
#include "11_sampling/warp.h"
#include "13_lights/point_light.h"

namespace rtk {

// [ch13-distant]
/// A distant light of radiance L filling a cone of half-angle theta_max around the direction
/// it comes from (the guide's -distantlight dx dy dz r g b halfAngle, the angle in degrees;
/// `direction` is the way the light travels). Unlike the directional light it has a size, so
/// rays that hit it by chance see it (le) and MIS can weigh them. Sampling is uniform in the
/// cone: pdf = 1 / (2 pi (1 - cos theta_max)). The cone is held by 1 - cos theta_max, not by
/// the cosine, and a direction is inside when 1 - cos theta, computed from the difference of
/// the two unit vectors, is no more: a cosine near 1 has too few digits for a cone as small as
/// the sun (0.27 degrees), and none at all below 0.014 degrees.
class DistantLight final : public Light {
 public:
  /// A cone light; throws std::invalid_argument unless 0 < half_angle_degrees <= 180.
  DistantLight(Vec3f direction, Color radiance, float half_angle_degrees)
      : frame_(-detail::checked_direction(direction, "distant light direction")),
        radiance_(detail::checked_radiance(radiance, "distant light radiance")) {
    if (!(half_angle_degrees > 0.0f && half_angle_degrees <= 180.0f))
      throw std::invalid_argument(
          "distant light half-angle must lie in (0, 180] degrees (use a directional light for 0)");
    one_minus_cos_max_ = one_minus_cos(half_angle_degrees * kPi / 180.0f);
  }
  std::optional<LightSample> sample_li(const LightQuery&, Vec2f u) const override {
    const Vec3f wi = normalize(frame_.to_world(sample_uniform_cone(u, one_minus_cos_max_)));
    return LightSample{wi, radiance_, pdf_uniform_cone(one_minus_cos_max_),
                       std::numeric_limits<float>::infinity(), false};
  }
  float pdf_li(const LightQuery&, Vec3f wi) const override {
    return inside(wi) ? pdf_uniform_cone(one_minus_cos_max_) : 0.0f;
  }
  Color le(Vec3f wi) const override { return inside(wi) ? radiance_ : Color{}; }
  /// The irradiance at normal incidence, L pi sin^2(theta_max) (the cone's projected solid
  /// angle), through the scene's cross-section.
  Color power(float scene_radius) const override {
    const float sin2 = one_minus_cos_max_ * (2.0f - one_minus_cos_max_);
    return radiance_ * (kPi * sin2 * kPi * scene_radius * scene_radius);
  }
  bool is_infinite() const override { return true; }

 private:
  bool inside(Vec3f wi) const { return one_minus_cos_between(normalize(wi), frame_.n) <= one_minus_cos_max_; }
  Frame frame_;  // n: the direction toward the light
  Color radiance_;
  float one_minus_cos_max_ = 0.0f;
};
// [ch13-distant]

/// A uniform sky of radiance L in every direction (the guide's -ambientlight r g b). With a
/// surface normal it is sampled with the cosine distribution around it, which cancels the
/// cosine of the rendering equation; without one, uniformly over the sphere.
class AmbientLight final : public Light {
 public:
  /// A sky of radiance `radiance`.
  explicit AmbientLight(Color radiance)
      : radiance_(detail::checked_radiance(radiance, "ambient light radiance")) {}
  std::optional<LightSample> sample_li(const LightQuery& q, Vec2f u) const override {
    if (has_normal(q)) {
      const Vec3f wi = normalize(Frame(normalize(q.n)).to_world(sample_cosine_hemisphere(u)));
      const float pdf = pdf_li(q, wi);
      if (!(pdf > 0.0f)) return std::nullopt;
      return LightSample{wi, radiance_, pdf, std::numeric_limits<float>::infinity(), false};
    }
    return LightSample{sample_uniform_sphere(u), radiance_, pdf_uniform_sphere(),
                       std::numeric_limits<float>::infinity(), false};
  }
  float pdf_li(const LightQuery& q, Vec3f wi) const override {
    return has_normal(q) ? pdf_cosine_hemisphere(dot(wi, normalize(q.n))) : pdf_uniform_sphere();
  }
  Color le(Vec3f) const override { return radiance_; }
  /// pi L onto every point of the bounding sphere's surface: 4 pi^2 r^2 L.
  Color power(float scene_radius) const override {
    return radiance_ * (4.0f * kPi * kPi * scene_radius * scene_radius);
  }
  bool is_infinite() const override { return true; }

 private:
  static bool has_normal(const LightQuery& q) {
    return is_finite(q.n) && (q.n.x != 0 || q.n.y != 0 || q.n.z != 0);
  }
  Color radiance_;
};

}  // namespace rtk
