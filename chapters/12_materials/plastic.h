/// \file
/// Plastic: a diffuse pigment under a clear dielectric coat, smooth or rough.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "11_sampling/warp.h"
#include "12_materials/bsdf_sample.h"
#include "12_materials/fresnel.h"
#include "12_materials/microfacet.h"

namespace rtk {

// [ch12-plastic]
/// A coated diffuse surface (the guide's Plastic): the coat reflects specularly with the
/// dielectric Fresnel term (a delta lobe when alpha = 0, GGX otherwise); what it transmits
/// reaches the pigment, is scattered diffusely and leaves through the coat again:
///   f = f_coat(wo, wi) + (1 - F(cos_o)) (1 - F(cos_i)) pigment / pi.
/// Both terms are symmetric, so the BRDF is reciprocal; the diffuse albedo is at most
/// (1 - F(cos_o)) pigment, so a smooth coat never reflects more than it receives. (The light
/// that the coat reflects back down onto the pigment is neglected: a documented darkening of
/// a few percent for white pigments.) A sample picks the coat with probability
/// F(cos_o) / (F(cos_o) + (1 - F(cos_o)) avg(pigment)) and the pigment otherwise.
struct Plastic {
  Color pigment{0.5f};
  float eta = 1.5f;
  GgxDistribution ggx{0.0f};  // alpha = 0: a smooth coat

  bool smooth() const { return ggx.alpha == 0.0f; }

  float coat_probability(float cos_o) const {
    const float f = fresnel_dielectric(cos_o, eta);
    const float total = f + (1.0f - f) * average(pigment);
    return total > 0.0f ? f / total : 0.0f;
  }

  Color eval(Vec3f wo, Vec3f wi) const {
    if (!same_hemisphere(wo, wi)) return {};
    wo = to_upper(wo), wi = to_upper(wi);
    const float t = (1.0f - fresnel_dielectric(wo.z, eta)) * (1.0f - fresnel_dielectric(wi.z, eta));
    Color f = pigment * (t * kInvPi);
    if (!smooth()) {
      const Vec3f m = normalize(wo + wi);
      f += Color(fresnel_dielectric(dot(wo, m), eta) * ggx.d(m) * ggx.g2(wo, wi) /
                 (4.0f * wo.z * wi.z));
    }
    return f;
  }

  float pdf(Vec3f wo, Vec3f wi) const {
    if (!same_hemisphere(wo, wi)) return 0.0f;
    wo = to_upper(wo), wi = to_upper(wi);
    const float p_coat = coat_probability(wo.z);
    float pdf = (1.0f - p_coat) * wi.z * kInvPi;
    if (!smooth()) {
      const Vec3f m = normalize(wo + wi);
      const float wo_m = dot(wo, m);
      if (wo_m > 0.0f) pdf += p_coat * ggx.pdf_visible(wo, m) / (4.0f * wo_m);
    }
    return pdf;
  }

  std::optional<BsdfSample> sample(Vec3f wo, float u_lobe, Vec2f u) const {
    if (wo.z == 0.0f) return std::nullopt;
    const bool flipped = wo.z < 0.0f;
    const Vec3f wo_up = to_upper(wo);
    const float p_coat = coat_probability(wo_up.z);
    Vec3f wi;
    if (u_lobe < p_coat) {
      if (smooth()) {
        // The coat's mirror reflection: a delta lobe chosen with probability p_coat.
        const float f = fresnel_dielectric(wo_up.z, eta);
        wi = reflect_local(wo);
        return BsdfSample{wi, Color(f / wo_up.z), Color(f / p_coat), p_coat, true};
      }
      wi = reflect(wo_up, ggx.sample_visible(wo_up, u));
    } else {
      wi = sample_cosine_hemisphere(u);
    }
    if (wi.z <= 0.0f) return std::nullopt;
    // One-sample MIS over the lobes: the weight uses the whole BRDF and the mixture density.
    const Color f = eval(wo_up, wi);
    const float pdf = this->pdf(wo_up, wi);
    if (!(pdf > 0.0f)) return std::nullopt;
    if (flipped) wi.z = -wi.z;
    return BsdfSample{wi, f, f * (std::fabs(wi.z) / pdf), pdf, false};
  }
};
// [ch12-plastic]

}  // namespace rtk
