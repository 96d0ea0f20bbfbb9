/// \file
/// Smooth opaque reflectors: the perfect mirror and the smooth conductor. Both reflect every
/// ray into one direction (a Dirac delta lobe), so eval and pdf are zero and only sample works.
#pragma once

#include <cmath>
#include <optional>

#include "12_materials/bsdf_sample.h"
#include "12_materials/fresnel.h"

namespace rtk {

/// A perfect mirror with a constant reflectance (the guide's Mirror material).
struct Mirror {
  Color reflectance{1.0f};

  Color eval(Vec3f, Vec3f) const { return {}; }
  float pdf(Vec3f, Vec3f) const { return 0.0f; }
  std::optional<BsdfSample> sample(Vec3f wo, float, Vec2f) const {
    if (wo.z == 0.0f) return std::nullopt;
    const Vec3f wi = reflect_local(wo);
    return BsdfSample{wi, reflectance / std::fabs(wi.z), reflectance, 1.0f, true};
  }
};

// [ch12-smooth-conductor]
/// A polished metal: a mirror whose reflectance is the conductor Fresnel term of its complex
/// index of refraction eta + i k, so it brightens and whitens toward grazing angles.
struct SmoothConductor {
  Color eta{0.2f, 0.92f, 1.1f};  // gold-like defaults
  Color k{3.9f, 2.45f, 2.14f};
  Color reflectance{1.0f};  ///< Embree 1.1 Metal's colour, a factor on the Fresnel term

  Color eval(Vec3f, Vec3f) const { return {}; }
  float pdf(Vec3f, Vec3f) const { return 0.0f; }
  std::optional<BsdfSample> sample(Vec3f wo, float, Vec2f) const {
    if (wo.z == 0.0f) return std::nullopt;
    const Vec3f wi = reflect_local(wo);
    const Color f = reflectance * fresnel_conductor(wo.z, eta, k);
    return BsdfSample{wi, f / std::fabs(wi.z), f, 1.0f, true};
  }
};
// [ch12-smooth-conductor]

}  // namespace rtk
