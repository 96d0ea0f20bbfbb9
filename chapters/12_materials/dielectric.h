/// \file
/// Smooth dielectrics: solid glass (reflection and refraction) and a thin glass sheet
/// (reflection and straight transmission). Both are purely specular.
#pragma once

#include <cmath>
#include <optional>

#include "12_materials/bsdf_sample.h"
#include "12_materials/fresnel.h"

namespace rtk {

// [ch12-dielectric]
/// The interface between two dielectrics (the guide's Dielectric / glass material). The
/// normal points to the outside; eta = eta_inside / eta_outside. A sample reflects with the
/// exact Fresnel probability F and refracts otherwise, so each branch has weight 1 apart
/// from two factors of the refracted branch: the transmission colour, and the radiance
/// scale 1 / eta_rel^2 (radiance is compressed into a smaller solid angle when it enters a
/// denser medium; Veach's thesis, section 5.2). With that factor the BSDF is not symmetric
/// but obeys f(wo, wi) / n_i^2 = f(wi, wo) / n_o^2.
struct SmoothDielectric {
  float eta = 1.5f;
  Color transmission{1.0f};

  Color eval(Vec3f, Vec3f) const { return {}; }
  float pdf(Vec3f, Vec3f) const { return 0.0f; }

  std::optional<BsdfSample> sample(Vec3f wo, float u_lobe, Vec2f) const {
    if (wo.z == 0.0f) return std::nullopt;
    const float cos_o = std::fabs(wo.z);
    const float eta_rel = wo.z > 0.0f ? eta : 1.0f / eta;  // n_transmitted / n_incident
    const float fresnel = fresnel_dielectric(wo.z, eta);
    if (u_lobe < fresnel) {
      const Vec3f wi = reflect_local(wo);
      return BsdfSample{wi, Color(fresnel / cos_o), Color(1.0f), fresnel, true};
    }
    const Vec3f n{0.0f, 0.0f, wo.z > 0.0f ? 1.0f : -1.0f};
    const std::optional<Vec3f> wt = refract(wo, n, eta_rel);
    if (!wt) return std::nullopt;  // unreachable: F = 1 under total internal reflection
    const Color weight = transmission * (1.0f / (eta_rel * eta_rel));
    const float pdf = 1.0f - fresnel;
    return BsdfSample{*wt, weight * (pdf / std::fabs(wt->z)), weight, pdf, true};
  }
};
// [ch12-dielectric]

// [ch12-thin-dielectric]
/// A thin sheet of glass (a window pane; the guide's ThinDielectric): light either reflects
/// or passes straight through, displaced by a negligible amount. The sheet's two interfaces
/// reflect back and forth; summing the geometric series of the inner bounces gives, with
/// F the interface's Fresnel reflectance and A the absorption of one crossing,
///   R = F + (1 - F)^2 F A^2 / (1 - F^2 A^2),   T = (1 - F)^2 A / (1 - F^2 A^2),
/// and R + T = 1 when A = 1. A = transmission^(thickness / cos_t) follows Beer's law along the
/// refracted path inside the sheet.
struct ThinDielectric {
  float eta = 1.5f;
  Color transmission{1.0f};
  float thickness = 0.1f;

  Color eval(Vec3f, Vec3f) const { return {}; }
  float pdf(Vec3f, Vec3f) const { return 0.0f; }

  /// The sheet's total reflectance and transmittance at incident cosine cos_o.
  void reflect_transmit(float cos_o, Color& r, Color& t) const {
    const float f = fresnel_dielectric(cos_o, eta);
    const float cos_t = std::sqrt(std::max(0.0f, 1.0f - (1.0f - cos_o * cos_o) / (eta * eta)));
    const Color a = cos_t > 0.0f ? pow(transmission, thickness / cos_t) : Color{};
    const Color fa2 = Color(f * f) * a * a;
    const Color denominator = Color(1.0f) - fa2;
    r = Color(f) + Color((1.0f - f) * (1.0f - f) * f) * a * a / denominator;
    t = Color((1.0f - f) * (1.0f - f)) * a / denominator;
  }

  std::optional<BsdfSample> sample(Vec3f wo, float u_lobe, Vec2f) const {
    if (wo.z == 0.0f) return std::nullopt;
    const float cos_o = std::fabs(wo.z);
    Color r, t;
    reflect_transmit(cos_o, r, t);
    // Choose a branch in proportion to its average energy.
    const float pr = average(r), pt = average(t);
    if (pr + pt <= 0.0f) return std::nullopt;
    const float p_reflect = pr / (pr + pt);
    if (u_lobe < p_reflect)
      return BsdfSample{reflect_local(wo), r / cos_o, r / p_reflect, p_reflect, true};
    const float p_transmit = 1.0f - p_reflect;
    return BsdfSample{-wo, t / cos_o, t / p_transmit, p_transmit, true};
  }
};
// [ch12-thin-dielectric]

}  // namespace rtk
