/// \file
/// Velvet: a diffuse base that scatters light back toward where it came from, and a sheen at
/// grazing views, the look of cloth whose fibres stand up from the surface.
#pragma once

#include <cmath>
#include <optional>

#include "11_sampling/warp.h"
#include "12_materials/bsdf_sample.h"

namespace rtk {

// [ch12-velvet]
/// Embree 1.1's Velvet, two lobes over a cosine-sampled hemisphere:
///   - a back-scattering lobe, f = R / pi * max(0, wo . wi)^b: Lambertian when b = 0, and
///     for b > 0 brightest when light returns along the way it came, as the fibres' tips
///     reflect it;
///   - a horizon lobe, f = H / pi * (sin(theta_o)^s + sin(theta_i)^s) / 2: the sheen of
///     fibres seen side-on, which brightens a velvet surface toward its silhouette (s, the
///     falloff, narrows it). Half of it belongs to the view and half to the light, so that
///     the lobe is reciprocal, as physical scattering is.
/// Each lobe's value is at most its colour over pi, so with R + H <= 1 the surface reflects
/// at most what it receives.
struct Velvet {
  Color reflectance{0.4f};      ///< R: the back-scattering lobe's colour
  float back_scattering = 0.5f;  ///< b >= 0: how strongly light returns toward its source
  Color horizon{0.6f};           ///< H: the horizon lobe's colour (R + H <= 1 by default)
  float horizon_falloff = 10.0f;  ///< s >= 0: how close to the horizon the sheen stays

  Color eval(Vec3f wo, Vec3f wi) const {
    if (!same_hemisphere(wo, wi)) return {};
    const float back = std::pow(std::max(0.0f, dot(wo, wi)), back_scattering);
    const float sin_o = std::sqrt(std::max(0.0f, 1.0f - wo.z * wo.z));
    const float sin_i = std::sqrt(std::max(0.0f, 1.0f - wi.z * wi.z));
    const float sheen = 0.5f * (std::pow(sin_o, horizon_falloff) + std::pow(sin_i, horizon_falloff));
    return (reflectance * back + horizon * sheen) * kInvPi;
  }

  float pdf(Vec3f wo, Vec3f wi) const {
    return same_hemisphere(wo, wi) ? std::fabs(wi.z) * kInvPi : 0.0f;
  }

  std::optional<BsdfSample> sample(Vec3f wo, float /*u_lobe*/, Vec2f u) const {
    if (wo.z == 0.0f) return std::nullopt;
    Vec3f wi = sample_cosine_hemisphere(u);
    if (wi.z == 0.0f) return std::nullopt;
    if (wo.z < 0.0f) wi.z = -wi.z;
    const Color f = eval(wo, wi);
    // The cosine cancels against the density: the weight is pi f.
    return BsdfSample{wi, f, f * kPi, std::fabs(wi.z) * kInvPi, false};
  }
};
// [ch12-velvet]

}  // namespace rtk
