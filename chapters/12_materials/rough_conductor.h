/// \file
/// A rough metal: GGX microfacets, each a smooth conductor.
#pragma once

#include <cmath>
#include <optional>

#include "12_materials/bsdf_sample.h"
#include "12_materials/fresnel.h"
#include "12_materials/microfacet.h"

namespace rtk {

// [ch12-rough-conductor]
/// The Cook-Torrance microfacet BRDF with the GGX distribution, height-correlated Smith
/// masking and conductor Fresnel: f = D(m) G2(wo, wi) F(wo.m) / (4 cos_o cos_i), m the half
/// vector. Sampling draws a visible normal (Heitz 2018) and reflects wo about it, so the
/// weight is F G2 / G1(wo), never more than F: no fireflies at grazing angles.
/// Two-sided: a wo below the surface is mirrored to the upper side.
struct RoughConductor {
  Color eta{0.2f, 0.92f, 1.1f};
  Color k{3.9f, 2.45f, 2.14f};
  GgxDistribution ggx{0.1f};
  Color reflectance{1.0f};  ///< Embree 1.1 Metal's colour, a factor on the Fresnel term

  Color eval(Vec3f wo, Vec3f wi) const {
    if (!same_hemisphere(wo, wi)) return {};
    wo = to_upper(wo), wi = to_upper(wi);
    const Vec3f m = normalize(wo + wi);
    const float denominator = 4.0f * wo.z * wi.z;
    if (denominator == 0.0f) return {};
    return reflectance * fresnel_conductor(dot(wo, m), eta, k) * (ggx.d(m) * ggx.g2(wo, wi) / denominator);
  }

  float pdf(Vec3f wo, Vec3f wi) const {
    if (!same_hemisphere(wo, wi)) return 0.0f;
    wo = to_upper(wo), wi = to_upper(wi);
    const Vec3f m = normalize(wo + wi);
    const float wo_m = dot(wo, m);
    // The Jacobian of reflection, d(wi)/d(m) = 1 / (4 |wo.m|), turns the normals' density
    // into the directions' density.
    return wo_m > 0.0f ? ggx.pdf_visible(wo, m) / (4.0f * wo_m) : 0.0f;
  }

  std::optional<BsdfSample> sample(Vec3f wo, float, Vec2f u) const {
    if (wo.z == 0.0f) return std::nullopt;
    const bool flipped = wo.z < 0.0f;
    const Vec3f wo_up = to_upper(wo);
    const Vec3f m = ggx.sample_visible(wo_up, u);
    Vec3f wi = reflect(wo_up, m);
    if (wi.z <= 0.0f) return std::nullopt;  // reflected into the surface: the light is lost
    const float wo_m = dot(wo_up, m);
    if (!(wo_m > 0.0f)) return std::nullopt;
    const Color fresnel = reflectance * fresnel_conductor(wo_m, eta, k);
    const Color f = fresnel * (ggx.d(m) * ggx.g2(wo_up, wi) / (4.0f * wo_up.z * wi.z));
    const float pdf = ggx.pdf_visible(wo_up, m) / (4.0f * wo_m);
    const Color weight = fresnel * (ggx.g2(wo_up, wi) / ggx.g1(wo_up));
    if (flipped) wi.z = -wi.z;
    return BsdfSample{wi, f, weight, pdf, false};
  }
};
// [ch12-rough-conductor]

}  // namespace rtk
