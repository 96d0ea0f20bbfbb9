/// \file
/// The Lambertian BRDF: an ideal diffuse reflector.
#pragma once

#include <cmath>
#include <optional>

#include "11_sampling/warp.h"
#include "12_materials/bsdf_sample.h"

namespace rtk {

// [ch12-lambertian]
/// Light scattered equally in all directions of the hemisphere: f = R / pi, sampled with the
/// cosine distribution, so each sample's weight is exactly R.
struct Lambertian {
  Color reflectance{0.5f};

  Color eval(Vec3f wo, Vec3f wi) const {
    return same_hemisphere(wo, wi) ? reflectance * kInvPi : Color{};
  }

  float pdf(Vec3f wo, Vec3f wi) const {
    return same_hemisphere(wo, wi) ? std::fabs(wi.z) * kInvPi : 0.0f;
  }

  std::optional<BsdfSample> sample(Vec3f wo, float /*u_lobe*/, Vec2f u) const {
    if (wo.z == 0.0f) return std::nullopt;
    Vec3f wi = sample_cosine_hemisphere(u);
    if (wi.z == 0.0f) return std::nullopt;  // on the horizon: zero density, zero contribution
    if (wo.z < 0.0f) wi.z = -wi.z;
    return BsdfSample{wi, reflectance * kInvPi, reflectance, std::fabs(wi.z) * kInvPi, false};
  }
};
// [ch12-lambertian]

}  // namespace rtk
